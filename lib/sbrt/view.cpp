/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Views turned into cameras
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "view.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "error.hpp"

namespace sbrt {

double framing_distance(const Tracer &tracer, glm::dvec3 target, glm::dvec3 offset,
                        double fov, double aspect)
{
    const glm::dvec3 c = tracer.centre();
    const double r = tracer.radius();
    const double tan_y = std::tan(fov * M_PI / 360), tan_x = tan_y * aspect;
    const glm::dvec3 forward = -offset;
    glm::dvec3 right, up;
    view_basis(forward, right, up);
    auto fits = [&](double d) {
        const glm::dvec3 eye = target + offset * d;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 v = tracer.corner(k) - eye;
            const double z = glm::dot(v, forward);
            if (z <= 0)
                return false;
            if (std::fabs(glm::dot(v, right)) > 0.95 * tan_x * z ||
                std::fabs(glm::dot(v, up)) > 0.95 * tan_y * z)
                return false;
        }
        return true;
    };
    // bisection between the target and a distance that fits: the sphere
    // around the box within the narrower of the two half angles (a
    // portrait image's is the horizontal one), doubled until it fits
    const double half_angle = std::atan(std::min(tan_x, tan_y));
    double low = 0, high = (glm::length(target - c) + r) / std::sin(half_angle) * 1.1;
    for (int i = 0; i < 60 && !fits(high); ++i)
        high *= 2;
    for (int i = 0; i < 60; ++i) {
        const double mid = (low + high) / 2;
        (fits(mid) ? high : low) = mid;
    }
    return high;
}

Camera view_camera(const View &view, const Tracer &tracer, int rows, int cols)
{
    if (view.kind == ViewKind::top)
        fail("view_camera: a top view is the 2D region's (Camera::top)");
    const double radius = tracer.radius();
    const glm::dvec3 target = view.target ? tracer.exaggerate(*view.target) : tracer.centre();
    glm::dvec3 position;
    if (view.position) {
        position = tracer.exaggerate(*view.position);
    }
    else {
        // around the target: azimuth is where the camera looks from
        const double az = view.azimuth * M_PI / 180, el = view.elevation * M_PI / 180;
        const glm::dvec3 offset(std::sin(az) * std::cos(el), std::cos(az) * std::cos(el),
                                std::sin(el));
        const double distance =
            view.distance ? *view.distance
                          : framing_distance(tracer, target, offset, view.fov,
                                             double(cols) / rows);
        position = target + distance * offset;
    }
    if (view.kind == ViewKind::orthographic) {
        // rays start outside the model whatever position= says
        const glm::dvec3 dir = glm::normalize(target - position);
        const glm::dvec3 start =
            target - dir * (glm::length(tracer.centre() - target) + 2 * radius);
        return Camera::orthographic(start, target,
                                    view.ortho_height ? *view.ortho_height : 2.04 * radius,
                                    rows, cols);
    }
    return Camera::perspective(position, target, view.fov, rows, cols);
}

} // namespace sbrt
