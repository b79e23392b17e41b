/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Camera set-up
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_camera.hpp"
#include "request_error.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "image_memory.hpp"


namespace {

sbrt::ImageNeeds image_needs(const RenderRequest &request)
{
    sbrt::ImageNeeds needs;
    needs.kernel_normals = request.normals == sbrt::Normals::kernel;
    // an annotated PNG is drawn on the whole image (a plain one streams)
    if (!request.png.empty() && request.annotate && !request.tile)
        needs.whole_image_bytes_per_pixel = 3;
    return needs;
}

} // namespace

void check_image_fits(const RenderRequest &request, int rows, int cols)
{
    sbrt::check_image_fits(rows, cols, image_needs(request));
}

double image_memory(const RenderRequest &request, const struct Cell_head &region)
{
    const bool top = request.view.kind == sbrt::ViewKind::top;
    return sbrt::image_bytes(top ? region.rows : request.height,
                             top ? region.cols : request.width, image_needs(request));
}

sbrt::Camera make_camera(const RenderRequest &r, const sbrt::Model &model,
                         const sbrt::CoordinateFrame &frame,
                         const struct Cell_head &region)
{
    if (r.view.kind != sbrt::ViewKind::top) {
        check_image_fits(r, r.height, r.width);
        return sbrt::view_camera(r.view, model, frame, r.height, r.width);
    }
    const int rows = region.rows, cols = region.cols;
    check_image_fits(r, rows, cols);
    // georeferenced: one ray down through the centre of each region cell
    const sbrt::Frame &f = model.frame();
    if (!(region.west < f.east && region.east > f.west && region.south < f.north &&
          region.north > f.south))
        bad_request(_("view=top: the current region (n=%f s=%f e=%f w=%f) "
                        "does not overlap SBRT <%s> (n=%f s=%f e=%f w=%f); "
                        "set it with g.region (e.g. raster_3d= of the "
                        "source map)"),
                      region.north, region.south, region.east, region.west,
                      r.input.c_str(), f.north, f.south, f.east, f.west);
    return sbrt::Camera::top(region.north, region.south, region.east, region.west,
                             frame.centre().z + 2 * frame.radius() + 1, rows, cols);
}
