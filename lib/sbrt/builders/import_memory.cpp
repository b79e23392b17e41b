/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The least memory a file import needs, before it reads
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/import_memory.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// What an import holds for each cell of the model until it is written
/// (the model itself only a band at a time): the column's range packed
/// as the ranges member stores it (4 bytes) and the compressed stacks (a
/// byte a cell is more than GeoTOP-like columns take).
constexpr double BYTES_PER_CELL = 4 + 1;

std::string gigabytes(double bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
    return text;
}

} // namespace

double import_band_bytes(const ImportGrid &grid, uint64_t band_bytes)
{
    const double row = double(grid.cols) * double(grid.depths) * double(grid.sample_bytes);
    return 2 * std::max(row, double(band_bytes));
}

double import_bytes_at_least(const ImportGrid &grid, uint64_t band_bytes)
{
    const double cells = double(grid.cols) * double(grid.rows);
    const double coordinates = 8.0 * (double(grid.cols) + double(grid.rows) + double(grid.depths));
    return cells * BYTES_PER_CELL + coordinates + import_band_bytes(grid, band_bytes);
}

void check_import_fits(const ImportGrid &grid, uint64_t band_bytes, double available,
                       const std::string &what)
{
    const double cells = double(grid.cols) * double(grid.rows);
    const double max_cells = double(std::numeric_limits<int32_t>::max());
    if (cells > max_cells)
        fail(what, " has ", grid.cols, " x ", grid.rows, " = ", uint64_t(cells),
             " cells; an SBRT holds at most 2^31-1 (", uint64_t(max_cells),
             "). Import a part of it (e.g. gdalmdimtranslate -subset, ncks -d)");
    if (grid.depths > (uint64_t(1) << 24))
        fail(what, " has ", grid.depths, " depths; an SBRT holds at most 2^24 (",
             uint64_t(1) << 24, "). Import a part of it (e.g. ncks -d)");
    const double needed = import_bytes_at_least(grid, band_bytes);
    if (available > 0 && needed > available)
        fail(what, " (", grid.cols, " x ", grid.rows, " x ", grid.depths,
             " voxels) needs at least ", gigabytes(needed), " of memory to import (",
             BYTES_PER_CELL, " bytes for each of its ", uint64_t(cells),
             " cells and two bands of ",
             uint64_t(import_band_bytes(grid, band_bytes) / 2 / 1e6 + 0.5),
             " MB); this machine has ", gigabytes(available), " available. Import a part of it (e.g. "
             "gdalmdimtranslate -subset, ncks -d) or use a larger machine");
}

} // namespace sbrt
