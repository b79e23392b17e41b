/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Class ids -> material indices, and the material table
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/material_table.hpp"

#include "model/palette.hpp"

#include "util/error.hpp"

namespace sbrt {

uint32_t MaterialTable::lookup(int32_t id)
{
    auto found = material_of_class_.find(id);
    if (found != material_of_class_.end())
        return found->second;
    if (class_of_material_.size() >= MAX_MATERIALS)
        fail("more than ", MAX_MATERIALS - 1, " distinct classes (at class ", id,
             "): an SBRT holds at most ", MAX_MATERIALS - 1,
             "; group the values into classes (r3.sbrt.convert rules=)");
    const uint32_t index = uint32_t(class_of_material_.size());
    class_of_material_.push_back(id);
    material_of_class_.emplace(id, index);
    return index;
}

std::vector<Material>
MaterialTable::materials(const std::vector<Material> &legend) const
{
    std::vector<Material> materials(class_of_material_.size());
    for (size_t i = 1; i < materials.size(); ++i) {
        materials[i].id = class_of_material_[i];
        for (const Material &m : legend)
            if (m.id == materials[i].id)
                materials[i] = m;
    }
    materials[0].label = "EMPTY";
    return materials;
}

std::array<uint8_t, 3> material_color(const std::vector<Material> &materials,
                                      uint32_t material)
{
    const Material &m = materials[material];
    if (m.has_color)
        return {m.red, m.green, m.blue};
    // material 1 takes the palette's first entry: a model of n <= 30
    // classes gets n distinguishable colours
    return palette_color(material == EMPTY ? 0 : material - 1);
}

std::array<uint8_t, 3> material_color(const Model &model, uint32_t material)
{
    return material_color(model.materials(), material);
}

} // namespace sbrt
