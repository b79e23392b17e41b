/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   The current region and an SBRT's grid: -s sets the region to
 *            it in one step (2D and 3D, as g.region raster_3d= does); -r
 *            says when the region's 3D grid is another
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <cmath>

#include "grass.hpp"
#include "grass_window.hpp"

namespace {

bool near(double a, double b, double resolution)
{
    return std::fabs(a - b) <= 1e-6 * std::fabs(resolution);
}

} // namespace

void set_region_to(const char *name, const sbrt::Frame &frame)
{
    struct Cell_head current;
    G_get_window(&current);
    Cell_head window = sbrt_grass::window_of(frame, current);
    if (G_put_window(&window) < 0)
        G_fatal_error(_("Unable to write the current region"));
    // this process goes on in it too (-s with -r)
    G_set_window(&window);
    RASTER3D_Region region;
    Rast3d_region_from_to_cell_head(&window, &region);
    Rast3d_set_window(&region);
    G_message(_("Current region (2D and 3D) set to SBRT <%s>: %d rows x %d "
                "columns x %d depths"),
              name, frame.rows, frame.cols, frame.depths);
}

bool same_grid(const sbrt::Frame &a, const sbrt::Frame &b)
{
    return a.rows == b.rows && a.cols == b.cols && a.depths == b.depths &&
           near(a.north, b.north, a.ns_res()) && near(a.south, b.south, a.ns_res()) &&
           near(a.east, b.east, a.ew_res()) && near(a.west, b.west, a.ew_res()) &&
           near(a.top, b.top, a.tb_res()) && near(a.bottom, b.bottom, a.tb_res());
}

void warn_if_other_grid(const char *name, const sbrt::Frame &model,
                        const sbrt::Frame &region)
{
    if (same_grid(model, region))
        return;
    G_warning(_("The current 3D region (%d rows x %d columns x %d depths; n=%.15g "
                "s=%.15g e=%.15g w=%.15g t=%.15g b=%.15g) is not the grid of SBRT "
                "<%s> (%d x %d x %d; n=%.15g s=%.15g e=%.15g w=%.15g t=%.15g "
                "b=%.15g): the 3D raster map is resampled to the region, each "
                "voxel taking the class at its centre. To expand the SBRT voxel "
                "for voxel, set the region to it in one step with "
                "r3.sbrt.convert -s sbrt=%s (or add -s to this command)"),
              region.rows, region.cols, region.depths, region.north, region.south,
              region.east, region.west, region.top, region.bottom, name, model.rows,
              model.cols, model.depths, model.north, model.south, model.east,
              model.west, model.top, model.bottom, name);
}
