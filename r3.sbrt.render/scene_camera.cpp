/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Camera set-up
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_camera.hpp"

#include <algorithm>
#include <cmath>

#include <unistd.h>

#include <glm/geometric.hpp>

namespace {

/// Smallest distance along `offset` (unit) from `target` at which the eight
/// corners of the model's box lie inside 95 % of the image (bisection).
double framing_distance(const sbrt::Tracer &tracer, glm::dvec3 target,
                        glm::dvec3 offset, double fov, double aspect)
{
    const glm::dvec3 c = tracer.centre();
    const double r = tracer.radius();
    const double tan_y = std::tan(fov * M_PI / 360), tan_x = tan_y * aspect;
    const glm::dvec3 forward = -offset;
    glm::dvec3 right, up;
    sbrt::view_basis(forward, right, up);
    auto fits = [&](double d) {
        const glm::dvec3 eye = target + offset * d;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 corner = tracer.corner(k);
            const glm::dvec3 v = corner - eye;
            const double z = glm::dot(v, forward);
            if (z <= 0)
                return false;
            if (std::fabs(glm::dot(v, right)) > 0.95 * tan_x * z ||
                std::fabs(glm::dot(v, up)) > 0.95 * tan_y * z)
                return false;
        }
        return true;
    };
    double low = 0, high = (glm::length(target - c) + r) / std::sin(fov * M_PI / 360) * 1.1;
    for (int i = 0; i < 60; ++i) {
        const double mid = (low + high) / 2;
        (fits(mid) ? high : low) = mid;
    }
    return high;
}

} // namespace

void check_image_fits(int rows, int cols, bool kernel_normals)
{
    // streamed: two bands in flight, each of hits (72 bytes) and outputs
    // (rgb, class, elevation, depth: 23) per pixel, 64 rows at most; the
    // kernel's window of rows may reach the whole image (a camera inside
    // the model), with its depths and smoothing (32 bytes)
    const double per_pixel = double(sizeof(sbrt::Hit) + 23);
    const double needed =
        kernel_normals ? double(rows) * cols * (per_pixel + 32)
                       : 2.0 * std::min(rows, 64) * double(cols) * per_pixel;
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (memory > 0 && needed > 0.8 * memory)
        G_fatal_error(_("An image of %d x %d pixels needs about %.1f GB of memory "
                        "for its rays and outputs%s; this machine has %.1f GB. "
                        "Set fewer rows and columns (g.region rows= cols=) and "
                        "render the view in parts, or use a larger machine."),
                      cols, rows, needed / 1e9,
                      kernel_normals ? _(" with normals=kernel") : "", memory / 1e9);
}

sbrt::Camera make_camera(const RenderRequest &r, const sbrt::Tracer &tracer,
                         const struct Cell_head &region)
{
    const int rows = region.rows, cols = region.cols;
    check_image_fits(rows, cols, r.normals == "kernel");
    const double radius = tracer.radius();
    if (r.view == "top") {
        const sbrt::Frame &f = tracer.model().frame();
        if (!(region.west < f.east && region.east > f.west && region.south < f.north &&
              region.north > f.south))
            G_fatal_error(_("view=top: the current region (n=%f s=%f e=%f w=%f) "
                            "does not overlap SBRT <%s> (n=%f s=%f e=%f w=%f); "
                            "set it with g.region (e.g. raster_3d= of the "
                            "source map)"),
                          region.north, region.south, region.east, region.west,
                          r.input.c_str(), f.north, f.south, f.east, f.west);
        return sbrt::Camera::top(region.north, region.south, region.east,
                                 region.west,
                                 tracer.centre().z + 2 * radius + 1, rows,
                                 cols);
    }

    const glm::dvec3 target =
        r.target ? tracer.exaggerate(*r.target) : tracer.centre();
    glm::dvec3 position;
    if (r.position) {
        position = tracer.exaggerate(*r.position);
    }
    else {
        // around the target: azimuth is where the camera looks from
        const double az = r.azimuth * M_PI / 180, el = r.elevation * M_PI / 180;
        const glm::dvec3 offset(std::sin(az) * std::cos(el),
                                std::cos(az) * std::cos(el), std::sin(el));
        const double distance =
            r.distance ? *r.distance
                       : framing_distance(tracer, target, offset, r.fov,
                                          double(cols) / rows);
        position = target + distance * offset;
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
