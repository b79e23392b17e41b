/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Hidden classes and clip planes
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_setup.hpp"

#include <cstdlib>
#include <string>

#include <glm/geometric.hpp>

std::vector<uint32_t> hidden_materials(const RenderRequest &request,
                                       const sbrt::Model &model)
{
    const std::vector<sbrt::Material> &materials = model.materials();
    std::vector<uint32_t> hidden;
    for (const std::string &name : request.hide) {
        char *end = nullptr;
        const long id = std::strtol(name.c_str(), &end, 10);
        const bool numeric = !name.empty() && *end == '\0';
        uint32_t found = sbrt::EMPTY;
        for (uint32_t i = 1; i < materials.size() && found == sbrt::EMPTY; ++i)
            if ((numeric && materials[i].id == id) ||
                G_strcasecmp(materials[i].label.c_str(), name.c_str()) == 0)
                found = i;
        if (found == sbrt::EMPTY) {
            std::string classes;
            for (uint32_t i = 1; i < materials.size(); ++i)
                classes += (i > 1 ? ", " : "") + std::to_string(materials[i].id) +
                           (materials[i].label.empty() ? "" : " (" + materials[i].label + ")");
            G_fatal_error(_("hide=%s: SBRT <%s> has no class with this id or "
                            "label; its classes are %s"),
                          name.c_str(), request.input.c_str(), classes.c_str());
        }
        hidden.push_back(found);
    }
    return hidden;
}

std::vector<sbrt::ClipPlane> clip_planes(const RenderRequest &request,
                                         const sbrt::Camera &camera)
{
    std::vector<sbrt::ClipPlane> planes;
    for (const auto &p : request.planes)
        planes.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}});
    if (request.section) {
        const auto &s = *request.section;
        const glm::dvec3 point(s[0], s[1], 0);
        // horizontal normal to the left of (x1,y1) -> (x2,y2)
        glm::dvec3 normal(-(s[3] - s[1]), s[2] - s[0], 0);
        // towards the camera: the side the camera is on is removed
        const double facing = camera.parallel()
                                  ? glm::dot(normal, -camera.forward())
                                  : glm::dot(normal, camera.origin() - point);
        if (facing < 0)
            normal = -normal;
        planes.push_back({point, normal});
    }
    return planes;
}
