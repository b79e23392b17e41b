/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The class profile as a raster map: columns along the line,
 *            rows in elevation, in a window of distance by height
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROFILE_MAP_HPP
#define R3_SBRT_PROFILE_MAP_HPP

#include <optional>
#include <string>

#include "grass.hpp"
#include "model/model.hpp"
#include "measure/class_profile.hpp"

/// \brief The map's grid: `cols` steps along the line, one row per layer
/// of the model (its vertical resolution) from the lowest layer's bottom
/// to the highest layer's top under the line.
struct ProfileGrid {
    int rows = 0, cols = 0;
    sbrt::ProfileExtent extent;
};

/// Columns of a line `length` long at `step` (rounded so that they fill
/// it): at least 1; a fatal error beyond a million.
int profile_columns(double length, double step);

/// The grid of the map of `model` along `line` in `cols` columns; nothing
/// where the line meets no layer.
std::optional<ProfileGrid> profile_grid(const sbrt::Model &model, const sbrt::ProfileLine &line,
                                        int cols);

/// The map's window: west 0 and east the line's length (x is the distance
/// along it), south and north the grid's elevations (y is the height).
struct Cell_head profile_window(const ProfileGrid &grid, double length);

/// Writes `profile` as raster map `name` (CELL: class ids, null where
/// nothing is) in its window, with the model's colours and labels, a
/// title and history naming the SBRT and the line (cut to what GRASS
/// keeps).
void write_profile_map(const std::string &name, const sbrt::ClassProfile &profile,
                       const sbrt::Model &model, const std::string &input,
                       const std::string &line_text);

#endif
