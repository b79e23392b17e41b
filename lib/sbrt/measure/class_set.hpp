/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A set of a model's classes named by class id or label, as
 *            the material indices the intervals hold
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CLASS_SET_HPP
#define SBRT_CLASS_SET_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief Material indices of a model (never EMPTY), with a flag per
/// material for the column loops.
class ClassSet {
public:
    ClassSet() = default;
    /// The classes `names` names: each a class id or a label (labels
    /// compared without regard to case, ids first, as r3.sbrt.render's
    /// hide= reads them); throws sbrt::Error naming the first unknown one
    /// and listing the model's classes. Duplicates count once.
    static ClassSet named(const Model &model, const std::vector<std::string> &names);
    /// The set of material indices `materials` (each 1 .. materials - 1).
    static ClassSet of_materials(const Model &model, const std::vector<uint32_t> &materials);

    bool contains(uint32_t material) const
    {
        return material < member_.size() && member_[material];
    }
    /// Material indices, ascending.
    const std::vector<uint32_t> &materials() const { return materials_; }
    /// "id (label), ..." of the set's classes by id, for messages and reports.
    std::string describe(const Model &model) const;

private:
    std::vector<uint8_t> member_;
    std::vector<uint32_t> materials_;
};

/// Material index of the class `name` (class id or label); throws
/// sbrt::Error naming it and listing the model's classes.
uint32_t find_class(const Model &model, const std::string &name);
/// "id (label)" of a material, "id" where it has no label.
std::string class_name(const Model &model, uint32_t material);
/// Every class of the model by id: "1 (Sand), 2 (Clay), ...".
std::string list_classes(const Model &model);

} // namespace sbrt

#endif
