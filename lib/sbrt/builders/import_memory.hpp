/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What an import of a gridded file variable needs before it
 *            reads a value: the grid's limits, and memory at least
 *            proportional to its cells, checked against what the machine
 *            has
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_IMPORT_MEMORY_HPP
#define SBRT_IMPORT_MEMORY_HPP

#include <cstdint>
#include <string>

namespace sbrt {

/// \brief The size of a variable to import: cells along each axis and the
/// bytes of one value read.
struct ImportGrid {
    uint64_t cols = 0, rows = 0, depths = 0;
    uint64_t sample_bytes = 8;
};

/// Bytes of the two bands in flight: `band_bytes` each, but at least one
/// northing row of whole columns.
double import_band_bytes(const ImportGrid &grid, uint64_t band_bytes);

/// The least an import of `grid` needs: per cell the column's range
/// (4 bytes, packed) and its compressed stack (about 1; the model is held
/// a band at a time); the coordinates read (8 bytes a value); two bands. Geological columns hold more intervals, so the
/// import takes more.
double import_bytes_at_least(const ImportGrid &grid, uint64_t band_bytes);

/// Throws sbrt::Error naming `what` when `grid` is no SBRT frame (at most
/// 2^31-1 cells, 2^24 depths), or when import_bytes_at_least exceeds
/// `available` bytes (0: unknown, not checked), with both figures and what
/// to do.
void check_import_fits(const ImportGrid &grid, uint64_t band_bytes, double available,
                       const std::string &what);

} // namespace sbrt

#endif
