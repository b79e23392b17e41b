/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Each column's range of material (the bottom of its lowest and
 *            the top of its highest solid interval): what the empty-space
 *            pyramid and the framing of a view read before any ray
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_RANGES_HPP
#define SBRT_COLUMN_RANGES_HPP

#include <vector>

#include "model/column_range_array.hpp"
#include "model/interval_array.hpp"
#include "model/z_range.hpp"

namespace sbrt {

class Model;
struct StackBlock;

/// Writes the ranges of `block`'s cells into `ranges` (the model's cells,
/// row by row, row 0 north; `cols` a row); returns the highest top (0
/// where all are empty).
double block_column_ranges(const StackBlock &block, int cols, std::vector<ZRange> &ranges);
/// The same as u16 pairs, for a model whose tops are voxel boundaries;
/// throws sbrt::Error where a range is not such a pair.
double block_column_ranges(const StackBlock &block, int cols, CompactRanges &ranges);

/// The ranges of a model decoded whole (row by row, row 0 north).
std::vector<ZRange> column_ranges(const Model &model);

/// Each column's top interval (row by row, row 0 north) as the `tops`
/// member stores it: its material (EMPTY: an empty column) and, in the
/// record's `top`, its bottom (0 where it is the column's only interval).
/// A ray that stays above that bottom in a column meets nothing else of
/// it: its top is the column range's high.
std::vector<Interval> column_tops(const Model &model);

} // namespace sbrt

#endif
