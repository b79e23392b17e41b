/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Which model cell each cell of another grid (the region) falls
 *            in, sampled at that cell's centre
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CENTRE_SAMPLING_HPP
#define SBRT_CENTRE_SAMPLING_HPP

#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief A 2D grid of map coordinates, row 0 north (a GRASS region).
struct GridWindow {
    double north = 1, south = 0, east = 1, west = 0;
    int rows = 1, cols = 1;
};

/// \brief For each row and column of a grid, the model's row and column
/// under its centre, -1 where the centre lies outside the model. A grid
/// equal to the model's gives every model cell once.
struct CentreSampling {
    std::vector<int> model_row; ///< per grid row
    std::vector<int> model_col; ///< per grid column
};

/// The model cells under the centres of `grid`'s cells; throws
/// sbrt::Error for a grid without cells or extent.
CentreSampling sample_at_centres(const Frame &frame, const GridWindow &grid);

/// The model's own grid as a GridWindow.
GridWindow model_grid(const Frame &frame);

} // namespace sbrt

#endif
