/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A set of a model's classes named by class id or label
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/class_set.hpp"

#include <algorithm>

#include "model/class_names.hpp"
#include "util/error.hpp"

namespace sbrt {

ClassSet ClassSet::named(const Model &model, const std::vector<std::string> &names)
{
    // ids, aliases and labels as every list option names classes
    return of_materials(model, ClassNames(model.materials()).resolve(names, "classes"));
}

ClassSet ClassSet::of_materials(const Model &model, const std::vector<uint32_t> &materials)
{
    return of_materials(model.materials(), materials);
}

ClassSet ClassSet::of_materials(const std::vector<Material> &table,
                                const std::vector<uint32_t> &materials)
{
    ClassSet set;
    set.member_.assign(table.size(), 0);
    for (uint32_t m : materials) {
        if (m == EMPTY || m >= set.member_.size())
            fail("ClassSet: material index ", m, " is no class of the model (1 .. ",
                 set.member_.size() - 1, ")");
        if (!set.member_[m])
            set.materials_.push_back(m);
        set.member_[m] = 1;
    }
    std::sort(set.materials_.begin(), set.materials_.end());
    return set;
}

std::string ClassSet::describe(const Model &model) const
{
    return describe(model.materials());
}

std::string ClassSet::describe(const std::vector<Material> &table) const
{
    // "id (label), ..." in the order of the class ids
    std::vector<uint32_t> materials = materials_;
    std::sort(materials.begin(), materials.end(), [&](uint32_t a, uint32_t b) {
        return table[a].id < table[b].id;
    });
    std::string out;
    for (const uint32_t i : materials) {
        const Material &m = table[i];
        out += (out.empty() ? "" : ", ") + std::to_string(m.id) +
               (m.label.empty() ? "" : " (" + m.label + ")");
    }
    return out;
}

} // namespace sbrt
