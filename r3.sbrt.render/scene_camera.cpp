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
                        "Render a smaller image (size=, or for view=top g.region "
                        "rows= cols=) or use a larger machine."),
                      cols, rows, needed / 1e9,
                      kernel_normals ? _(" with normals=kernel") : "", memory / 1e9);
}

sbrt::Camera make_camera(const RenderRequest &r, const sbrt::Tracer &tracer,
                         const struct Cell_head &region)
{
    if (r.view.kind != sbrt::ViewKind::top) {
        check_image_fits(r.height, r.width, r.normals == sbrt::Normals::kernel);
        return sbrt::view_camera(r.view, tracer, r.height, r.width);
    }
    const int rows = region.rows, cols = region.cols;
    check_image_fits(rows, cols, r.normals == sbrt::Normals::kernel);
    // georeferenced: one ray down through the centre of each region cell
    const sbrt::Frame &f = tracer.model().frame();
    if (!(region.west < f.east && region.east > f.west && region.south < f.north &&
          region.north > f.south))
        G_fatal_error(_("view=top: the current region (n=%f s=%f e=%f w=%f) "
                        "does not overlap SBRT <%s> (n=%f s=%f e=%f w=%f); "
                        "set it with g.region (e.g. raster_3d= of the "
                        "source map)"),
                      region.north, region.south, region.east, region.west,
                      r.input.c_str(), f.north, f.south, f.east, f.west);
    return sbrt::Camera::top(region.north, region.south, region.east, region.west,
                             tracer.centre().z + 2 * tracer.radius() + 1, rows, cols);
}
