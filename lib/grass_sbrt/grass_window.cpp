/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT's grid and GRASS's windows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "grass_window.hpp"

namespace sbrt_grass {

sbrt::Frame frame_of(const RASTER3D_Region &region)
{
    sbrt::Frame f;
    f.north = region.north;
    f.south = region.south;
    f.east = region.east;
    f.west = region.west;
    f.top = region.top;
    f.bottom = region.bottom;
    f.rows = region.rows;
    f.cols = region.cols;
    f.depths = region.depths;
    f.proj = region.proj;
    f.zone = region.zone;
    return f;
}

sbrt::Frame current_frame()
{
    RASTER3D_Region region;
    Rast3d_get_window(&region);
    return frame_of(region);
}

Cell_head window_of(const sbrt::Frame &frame, Cell_head base)
{
    base.north = frame.north;
    base.south = frame.south;
    base.east = frame.east;
    base.west = frame.west;
    base.top = frame.top;
    base.bottom = frame.bottom;
    base.rows = base.rows3 = frame.rows;
    base.cols = base.cols3 = frame.cols;
    base.depths = frame.depths;
    // resolutions (2D and 3D) from the counts
    G_adjust_Cell_head3(&base, 1, 1, 1);
    return base;
}

} // namespace sbrt_grass
