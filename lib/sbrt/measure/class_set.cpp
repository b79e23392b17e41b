/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A set of a model's classes named by class id or label
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/class_set.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include "util/error.hpp"

namespace sbrt {

namespace {

bool same_label(const std::string &a, const std::string &b)
{
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// The class id `name` spells, where it is a whole integer of 32 bits.
bool parse_id(const std::string &name, int32_t &id)
{
    if (name.empty())
        return false;
    char *end = nullptr;
    errno = 0;
    const long long value = std::strtoll(name.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || value < INT32_MIN || value > INT32_MAX)
        return false;
    id = int32_t(value);
    return true;
}

} // namespace

uint32_t find_class(const Model &model, const std::string &name)
{
    const std::vector<Material> &materials = model.materials();
    int32_t id = 0;
    if (parse_id(name, id) && id != NULL_CLASS) {
        const int64_t material = model.find_material(id);
        if (material > 0)
            return uint32_t(material);
    }
    for (uint32_t i = 1; i < materials.size(); ++i)
        if (!materials[i].label.empty() && same_label(materials[i].label, name))
            return i;
    fail("classes: the model has no class with id or label '", name,
         "'; its classes are ", list_classes(model));
}

std::string class_name(const Model &model, uint32_t material)
{
    const Material &m = model.materials().at(material);
    return std::to_string(m.id) + (m.label.empty() ? "" : " (" + m.label + ")");
}

/// "id (label), ..." of `materials`, in the order of their class ids.
static std::string names_by_id(const Model &model, std::vector<uint32_t> materials)
{
    std::sort(materials.begin(), materials.end(), [&](uint32_t a, uint32_t b) {
        return model.materials()[a].id < model.materials()[b].id;
    });
    std::string out;
    for (size_t i = 0; i < materials.size(); ++i)
        out += (i ? ", " : "") + class_name(model, materials[i]);
    return out;
}

std::string list_classes(const Model &model)
{
    std::vector<uint32_t> all;
    for (uint32_t i = 1; i < model.materials().size(); ++i)
        all.push_back(i);
    return all.empty() ? "none (the model is empty)" : names_by_id(model, all);
}

ClassSet ClassSet::named(const Model &model, const std::vector<std::string> &names)
{
    std::vector<uint32_t> materials;
    for (const std::string &name : names)
        materials.push_back(find_class(model, name));
    return of_materials(model, materials);
}

ClassSet ClassSet::of_materials(const Model &model, const std::vector<uint32_t> &materials)
{
    ClassSet set;
    set.member_.assign(model.materials().size(), 0);
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
    return names_by_id(model, materials_);
}

} // namespace sbrt
