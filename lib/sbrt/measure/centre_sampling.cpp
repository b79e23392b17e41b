/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Model cells under the centres of another grid's cells
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/centre_sampling.hpp"

#include <cmath>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// Index of the cell of [low, low + n * res) holding `v`, or -1.
int cell_of(double offset, double res, int n)
{
    const double k = std::floor(offset / res);
    return k >= 0 && k < n ? int(k) : -1;
}

} // namespace

CentreSampling sample_at_centres(const Frame &frame, const GridWindow &grid)
{
    if (grid.rows < 1 || grid.cols < 1 || !(grid.north > grid.south) ||
        !(grid.east > grid.west))
        fail("sample_at_centres: the grid has no cells (rows=", grid.rows,
             " cols=", grid.cols, " n=", grid.north, " s=", grid.south, " e=", grid.east,
             " w=", grid.west, ")");
    CentreSampling s;
    const double ns = (grid.north - grid.south) / grid.rows;
    const double ew = (grid.east - grid.west) / grid.cols;
    s.model_row.resize(size_t(grid.rows));
    for (int r = 0; r < grid.rows; ++r) {
        const double y = grid.north - (r + 0.5) * ns;
        s.model_row[size_t(r)] = cell_of(frame.north - y, frame.ns_res(), frame.rows);
    }
    s.model_col.resize(size_t(grid.cols));
    for (int c = 0; c < grid.cols; ++c) {
        const double x = grid.west + (c + 0.5) * ew;
        s.model_col[size_t(c)] = cell_of(x - frame.west, frame.ew_res(), frame.cols);
    }
    return s;
}

GridWindow model_grid(const Frame &frame)
{
    return {frame.north, frame.south, frame.east, frame.west, frame.rows, frame.cols};
}

} // namespace sbrt
