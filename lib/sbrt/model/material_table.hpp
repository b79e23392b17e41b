/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Class ids -> material indices while a builder meets them, and
 *            the model's material table with the source's legend
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MATERIAL_TABLE_HPP
#define SBRT_MATERIAL_TABLE_HPP

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief Numbers class ids in the order they are first met (1, 2, ...);
/// NULL_CLASS is EMPTY (0). At most MAX_MATERIALS - 1 classes.
class MaterialTable {
public:
    MaterialTable() : class_of_material_{NULL_CLASS} {}

    /// Material index of class `id`, added if new; throws sbrt::Error
    /// past MAX_MATERIALS - 1 classes.
    uint32_t material_of(int32_t id)
    {
        if (id == NULL_CLASS)
            return EMPTY;
        if (id == last_class_)
            return last_material_;
        last_class_ = id;
        last_material_ = lookup(id);
        return last_material_;
    }

    /// The table, EMPTY first; `legend` gives labels and colours by id.
    std::vector<Material> materials(const std::vector<Material> &legend) const;

private:
    uint32_t lookup(int32_t id);

    std::vector<int32_t> class_of_material_;
    std::unordered_map<int32_t, uint32_t> material_of_class_;
    int32_t last_class_ = NULL_CLASS;
    uint32_t last_material_ = EMPTY;
};

/// Colour of a material: its own colour, else entry material - 1 of the
/// default palette (model/palette.hpp).
std::array<uint8_t, 3> material_color(const std::vector<Material> &materials,
                                      uint32_t material);
std::array<uint8_t, 3> material_color(const Model &model, uint32_t material);

} // namespace sbrt

#endif
