/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Each column's range of material
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/column_ranges.hpp"

#include <algorithm>

#include "model/model.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

const auto solid = [](const auto &record) { return record.material != EMPTY; };

/// A column's range as `Range` holds it: a CompactRange only where it
/// is a pair of voxel boundaries a u16 holds (else the file is corrupt).
ZRange as_range(const ZRange &range, const ZRange *) { return range; }
CompactRange as_range(const ZRange &range, const CompactRange *)
{
    if (!fits_compact_range(range))
        fail("a column's range (", range.low, " to ", range.high,
             ") is not a pair of voxel boundaries, as the stacks' summary says every top is "
             "(corrupt file)");
    return range.empty() ? CompactRange{} : CompactRange{uint16_t(range.low), uint16_t(range.high)};
}

template <typename Ranges>
double block_ranges(const StackBlock &block, int cols, Ranges &ranges)
{
    double top = 0;
    block.intervals.visit([&](const auto *records) {
        for (int row = block.first_row; row < block.first_row + block.rows; ++row)
            for (int col = block.first_col; col < block.first_col + block.cols; ++col) {
                const StackRange s = block.range(row, col);
                const ZRange range = drawn_range(records + s.begin, records + s.end, solid);
                ranges[uint64_t(row) * uint64_t(cols) + uint64_t(col)] =
                    as_range(range, static_cast<const typename Ranges::value_type *>(nullptr));
                if (!range.empty())
                    top = std::max(top, double(range.high));
            }
    });
    return top;
}

} // namespace

double block_column_ranges(const StackBlock &block, int cols, std::vector<ZRange> &ranges)
{
    return block_ranges(block, cols, ranges);
}

double block_column_ranges(const StackBlock &block, int cols, CompactRanges &ranges)
{
    return block_ranges(block, cols, ranges);
}

std::vector<ZRange> column_ranges(const Model &model)
{
    if (const StackPages *pages = model.pages())
        return pages->column_ranges().widened_all();
    std::vector<ZRange> ranges(model.frame().cells());
    model.intervals().visit([&](const auto *records) {
        for (uint64_t cell = 0; cell < ranges.size(); ++cell) {
            const StackRange s = model.stack(cell);
            ranges[cell] = drawn_range(records + s.begin, records + s.end, solid);
        }
    });
    return ranges;
}

std::vector<Interval> column_tops(const Model &model)
{
    std::vector<Interval> tops(model.frame().cells(), Interval{EMPTY, 0.0f});
    for (uint64_t cell = 0; cell < tops.size(); ++cell)
        model.visit_stack(cell, [&](const auto *first, const auto *last) {
            if (first != last) // (no stack ends EMPTY)
                tops[cell] = {uint32_t((last - 1)->material),
                              last - first > 1 ? float((last - 2)->top) : 0.0f};
        });
    return tops;
}

} // namespace sbrt
