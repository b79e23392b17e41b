/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Camera set-up
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>

sbrt::Camera make_camera(const RenderRequest &r, const sbrt::Tracer &tracer,
                         const struct Cell_head &region)
{
    const int rows = region.rows, cols = region.cols;
    const double radius = tracer.radius();
    if (r.view == "top")
        return sbrt::Camera::top(region.north, region.south, region.east,
                                 region.west,
                                 tracer.centre().z + 2 * radius + 1, rows,
                                 cols);

    const glm::dvec3 target =
        r.target ? tracer.exaggerate(*r.target) : tracer.centre();
    glm::dvec3 position;
    if (r.position) {
        position = tracer.exaggerate(*r.position);
    }
    else {
        // around the target: azimuth is where the camera looks from
        const double az = r.azimuth * M_PI / 180, el = r.elevation * M_PI / 180;
        const double frame = radius / std::sin(r.fov * M_PI / 360) * 1.02;
        const double distance = r.distance ? *r.distance : frame;
        position = target + distance * glm::dvec3(std::sin(az) * std::cos(el),
                                                  std::cos(az) * std::cos(el),
                                                  std::sin(el));
    }
    if (r.view == "orthographic") {
        // rays start outside the model whatever position= says
        const glm::dvec3 dir = glm::normalize(target - position);
        const glm::dvec3 start =
            target - dir * (glm::length(tracer.centre() - target) + 2 * radius);
        return sbrt::Camera::orthographic(
            start, target, r.ortho_height ? *r.ortho_height : 2.04 * radius,
            rows, cols);
    }
    return sbrt::Camera::perspective(position, target, r.fov, rows, cols);
}
