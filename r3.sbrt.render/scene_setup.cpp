/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Hidden and translucent classes, clip planes
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_setup.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "scene/scene_parts.hpp"
#include "request_error.hpp"

uint32_t find_class(const sbrt::Model &model, const std::string &name,
                    const char *option, const std::string &input)
{
    const std::vector<sbrt::Material> &materials = model.materials();
    char *end = nullptr;
    const long id = std::strtol(name.c_str(), &end, 10);
    const bool numeric = !name.empty() && *end == '\0';
    for (uint32_t i = 1; i < materials.size(); ++i)
        if ((numeric && materials[i].id == id) ||
            G_strcasecmp(materials[i].label.c_str(), name.c_str()) == 0)
            return i;
    std::string classes;
    for (uint32_t i = 1; i < materials.size(); ++i)
        classes += (i > 1 ? ", " : "") + std::to_string(materials[i].id) +
                   (materials[i].label.empty() ? "" : " (" + materials[i].label + ")");
    bad_request(_("%s=%s: SBRT <%s> has no class with this id or label; its "
                    "classes are %s"),
                  option, name.c_str(), input.c_str(), classes.c_str());
}

std::vector<uint32_t> hidden_materials(const RenderRequest &request,
                                       const sbrt::Model &model)
{
    std::vector<uint32_t> hidden;
    for (const std::string &name : request.hide)
        hidden.push_back(find_class(model, name, "hide", request.input));
    return hidden;
}

sbrt::Translucency translucency(const RenderRequest &request,
                                const sbrt::Model &model)
{
    if (request.opacity.empty())
        return {};
    const sbrt::Frame &f = model.frame();
    std::vector<std::pair<uint32_t, double>> alphas;
    for (const auto &[name, alpha] : request.opacity)
        alphas.emplace_back(find_class(model, name, "opacity", request.input), alpha);
    return sbrt::make_translucency(
        model, alphas, request.opacity_length.value_or(std::sqrt(f.ew_res() * f.ns_res())));
}

std::vector<sbrt::ClipPlane> clip_planes(const RenderRequest &request,
                                         const sbrt::Camera &camera)
{
    std::vector<sbrt::ClipPlane> planes;
    for (const auto &p : request.planes)
        planes.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}});
    if (request.section) {
        const auto &s = *request.section;
        planes.push_back(sbrt::section_plane({s[0], s[1]}, {s[2], s[3]}, camera));
    }
    return planes;
}
