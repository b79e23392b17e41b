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
    /// The classes `names` names, as every list option names them
    /// (sbrt::ClassNames: an id, a preset's code or short name, a label);
    /// throws sbrt::Error naming the first unknown one and listing the
    /// model's classes. Duplicates count once.
    static ClassSet named(const Model &model, const std::vector<std::string> &names);
    /// The set of material indices `materials` (each 1 .. materials - 1).
    static ClassSet of_materials(const Model &model, const std::vector<uint32_t> &materials);
    /// The same from the model's material table alone (a model read band
    /// by band has it before any band).
    static ClassSet of_materials(const std::vector<Material> &table,
                                 const std::vector<uint32_t> &materials);

    bool contains(uint32_t material) const
    {
        return material < member_.size() && member_[material];
    }
    /// Material indices, ascending.
    const std::vector<uint32_t> &materials() const { return materials_; }
    /// "id (label), ..." of the set's classes by id, for messages and reports.
    std::string describe(const Model &model) const;
    std::string describe(const std::vector<Material> &table) const;

private:
    std::vector<uint8_t> member_;
    std::vector<uint32_t> materials_;
};

} // namespace sbrt

#endif
