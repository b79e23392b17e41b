/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Column by column voxel -> SBRT conversion
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/column_builder.hpp"

#include "format/format_v2.hpp"
#include "util/error.hpp"

namespace sbrt {

ColumnStackBuilder::ColumnStackBuilder(const Frame &frame)
    : frame_(frame), compact_(voxel_tops_fit_compact(frame.depths))
{
    frame_.validate("ColumnStackBuilder");
}

void ColumnStackBuilder::add_column(const int32_t *classes)
{
    runs_.clear();
    for (int z = 0; z < frame_.depths; ++z)
        if (z == 0 || classes[z] != classes[z - 1])
            runs_.push_back({classes[z], uint32_t(z + 1)});
        else
            runs_.back().top = uint32_t(z + 1);
    add_runs(runs_.data(), runs_.size());
}

void ColumnStackBuilder::add_runs(const ClassRun *runs, size_t count)
{
    if (cells_done() >= frame_.cells())
        fail("ColumnStackBuilder: more columns than the frame's ",
             frame_.cells(), " cells");
    if (count == 0 || runs[count - 1].top != uint32_t(frame_.depths))
        fail("ColumnStackBuilder: a column's runs must reach the top (",
             frame_.depths, ")");
    for (size_t r = 1; r < count; ++r)
        if (runs[r].top <= runs[r - 1].top)
            fail("ColumnStackBuilder: run tops must rise (", runs[r].top,
                 " after ", runs[r - 1].top, ")");
    if (runs[0].top == 0)
        fail("ColumnStackBuilder: a run must hold a voxel (top 0)");
    sizes_.push_back(compact_ ? append(compact_intervals_, runs, count)
                              : append(intervals_, runs, count));
}

template <typename Records>
uint32_t ColumnStackBuilder::append(Records &intervals, const ClassRun *runs, size_t count)
{
    using Record = typename Records::value_type;
    const size_t column_start = intervals.size();
    size_t solid_end = column_start; // after the last non-EMPTY run
    for (size_t r = 0; r < count; ++r) {
        const uint32_t material = table_.material_of(runs[r].id);
        const Record iv = voxel_interval<Record>(material, runs[r].top);
        if (intervals.size() > column_start && intervals.back().material == iv.material)
            intervals.back().top = iv.top;
        else
            intervals.push_back(iv);
        if (material != EMPTY)
            solid_end = intervals.size();
    }
    // air above the highest solid run is not stored
    intervals.resize(solid_end);
    return uint32_t(solid_end - column_start);
}

template <typename Records>
Model ColumnStackBuilder::band_model(Records &intervals, int rows,
                                     const std::vector<Material> &legend)
{
    const uint64_t cells = uint64_t(rows) * uint64_t(frame_.cols);
    const int first_row = int(cells_taken_ / uint64_t(frame_.cols));
    StackIndex index = StackIndex::from_sizes(sizes_.data(), cells);
    Records taken(intervals.begin(), intervals.begin() + ptrdiff_t(index.total()));
    intervals.erase(intervals.begin(), intervals.begin() + ptrdiff_t(index.total()));
    sizes_.erase(sizes_.begin(), sizes_.begin() + ptrdiff_t(cells));
    cells_taken_ += cells;
    return Model(frame_rows(frame_, first_row, rows), table_.materials(legend),
                 std::move(index), IntervalArray(std::move(taken)));
}

Model ColumnStackBuilder::take_rows(int count, const std::vector<Material> &legend)
{
    if (count < 1 || count > rows_ready())
        fail("ColumnStackBuilder: ", count, " rows asked for, ", rows_ready(), " ready");
    return compact_ ? band_model(compact_intervals_, count, legend)
                    : band_model(intervals_, count, legend);
}

Model ColumnStackBuilder::finish(const std::vector<Material> &legend)
{
    if (cells_done() != frame_.cells())
        fail("ColumnStackBuilder: got ", cells_done(), " columns, the frame has ",
             frame_.cells(), " cells");
    if (cells_taken_ > 0) {
        if (rows_ready() == 0)
            fail("ColumnStackBuilder: every row was taken (take_rows) before finish");
        return take_rows(rows_ready(), legend);
    }
    StackIndex index = StackIndex::from_sizes(sizes_.data(), sizes_.size());
    sizes_ = {};
    if (compact_)
        return Model(frame_, table_.materials(legend), std::move(index),
                     IntervalArray(std::move(compact_intervals_)));
    return Model(frame_, table_.materials(legend), std::move(index),
                 IntervalArray(std::move(intervals_)));
}

} // namespace sbrt
