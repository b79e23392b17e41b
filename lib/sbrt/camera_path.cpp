/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sequences of views: orbit and sweep
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "camera_path.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "error.hpp"

namespace sbrt {

glm::dvec3 turn_about_vertical(glm::dvec3 p, glm::dvec3 axis, double degrees)
{
    const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
    const glm::dvec2 d(p.x - axis.x, p.y - axis.y);
    return {axis.x + c * d.x - s * d.y, axis.y + s * d.x + c * d.y, p.z};
}

std::vector<Camera> orbit_cameras(const View &view, const Tracer &tracer, int rows,
                                  int cols, int frames, double angle)
{
    if (frames < 1)
        fail("orbit: ", frames, " frames; at least one");
    if (view.kind == ViewKind::top)
        fail("orbit: a top view does not turn (view=perspective or orthographic)");
    const std::vector<glm::dvec3> hull = framing_hull(tracer);
    const glm::dvec3 target =
        view.target ? tracer.exaggerate(*view.target) : tracer.centre();
    auto turn = [&](int k) { return (k - 1) * angle / frames; };
    // the direction from the target to the camera in frame 1
    glm::dvec3 offset;
    if (view.position) {
        offset = tracer.exaggerate(*view.position) - target;
        if (!(glm::length(offset) > 0))
            fail("orbit: position= and target= are the same point");
    }
    else {
        const double az = view.azimuth * M_PI / 180, el = view.elevation * M_PI / 180;
        offset = {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
    }
    const glm::dvec3 unit = glm::normalize(offset);
    const double aspect = double(cols) / rows;
    std::vector<Camera> cameras;
    if (view.kind == ViewKind::orthographic) {
        double height = view.ortho_height.value_or(0);
        if (!view.ortho_height) {
            // the largest extent about the target over all frames
            for (int k = 1; k <= frames; ++k) {
                const glm::dvec3 forward = -turn_about_vertical(unit, {0, 0, 0}, turn(k));
                glm::dvec3 right, up;
                view_basis(forward, right, up);
                right = glm::normalize(right);
                up = glm::normalize(up);
                for (const glm::dvec3 &p : hull) {
                    const glm::dvec3 v = p - target;
                    height = std::max({height, 2 * std::fabs(glm::dot(v, up)),
                                       2 * std::fabs(glm::dot(v, right)) / aspect});
                }
            }
            height /= 0.95;
        }
        const double reach = tracer.radius() + glm::length(tracer.centre() - target);
        for (int k = 1; k <= frames; ++k) {
            const glm::dvec3 u = turn_about_vertical(unit, {0, 0, 0}, turn(k));
            cameras.push_back(Camera::orthographic(target + u * (reach + tracer.radius()),
                                                   target, height, rows, cols));
        }
        return cameras;
    }
    // frame 1's position: position= as given (each frame then is exactly
    // the single view from the turned position), else at the distance
    glm::dvec3 first = target + offset;
    if (!view.position) {
        double distance = view.distance.value_or(0);
        if (!view.distance)
            for (int k = 1; k <= frames; ++k)
                distance = std::max(
                    distance, framing_distance(hull, target,
                                               turn_about_vertical(unit, {0, 0, 0}, turn(k)),
                                               view.fov, aspect));
        first = target + unit * distance;
    }
    else {
        first = tracer.exaggerate(*view.position);
    }
    for (int k = 1; k <= frames; ++k)
        cameras.push_back(Camera::perspective(turn_about_vertical(first, target, turn(k)),
                                              target, view.fov, rows, cols));
    return cameras;
}

ClipPlane swept_plane(const ClipPlane &plane, const Tracer &tracer, int frame, int frames)
{
    if (frames < 1 || frame < 1 || frame > frames)
        fail("sweep: frame ", frame, " of ", frames);
    const double length = glm::length(plane.normal);
    if (!(length > 0))
        fail("sweep: the plane's normal is zero");
    const glm::dvec3 n = plane.normal / length;
    // the box's extent along the normal (real map coordinates)
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (int k = 0; k < 8; ++k) {
        const double t = glm::dot(tracer.unexaggerate(tracer.corner(k)), n);
        low = std::min(low, t);
        high = std::max(high, t);
    }
    const double at = high - (high - low) * (frame - 1) / frames;
    const glm::dvec3 point = plane.point + (at - glm::dot(plane.point, n)) * n;
    return {point, plane.normal};
}

} // namespace sbrt
