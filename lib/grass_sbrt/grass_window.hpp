/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT's grid (sbrt::Frame) and GRASS's windows: the 3D
 *            region as a Frame, a Frame as a region (2D and 3D)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRASS_WINDOW_HPP
#define SBRT_GRASS_WINDOW_HPP

#include "grass.hpp"
#include "model/model.hpp"

namespace sbrt_grass {

/// The grid of a 3D region (its edges, counts, projection and zone).
sbrt::Frame frame_of(const RASTER3D_Region &region);
/// The current 3D region (Rast3d_get_window) as a grid.
sbrt::Frame current_frame();

/// `base` (projection, zone and whatever else it holds) with the grid of
/// `frame` in both its 2D and its 3D part: edges and counts as `frame`
/// has them, resolutions from the counts (G_adjust_Cell_head3).
Cell_head window_of(const sbrt::Frame &frame, Cell_head base);

} // namespace sbrt_grass

#endif
