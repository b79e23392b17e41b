/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Column by column voxel -> SBRT conversion
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "column_builder.hpp"

#include "error.hpp"

namespace sbrt {

ColumnStackBuilder::ColumnStackBuilder(const Frame &frame) : frame_(frame)
{
    frame_.validate("ColumnStackBuilder");
    offsets_.reserve(frame_.cells() + 1);
    offsets_.push_back(0);
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
    const size_t column_start = intervals_.size();
    size_t solid_end = column_start; // after the last non-EMPTY run
    for (size_t r = 0; r < count; ++r) {
        const uint32_t material = table_.material_of(runs[r].id);
        if (intervals_.size() > column_start &&
            intervals_.back().material == material)
            intervals_.back().top = float(runs[r].top);
        else
            intervals_.push_back({material, float(runs[r].top)});
        if (material != EMPTY)
            solid_end = intervals_.size();
    }
    // air above the highest solid run is not stored
    intervals_.resize(solid_end);
    if (intervals_.size() > UINT32_MAX)
        fail("ColumnStackBuilder: more than 2^32-1 intervals");
    offsets_.push_back(uint32_t(intervals_.size()));
}

Model ColumnStackBuilder::finish(const std::vector<Material> &legend)
{
    if (cells_done() != frame_.cells())
        fail("ColumnStackBuilder: got ", cells_done(), " columns, the frame has ",
             frame_.cells(), " cells");
    return Model(frame_, table_.materials(legend), std::move(offsets_),
                 std::move(intervals_));
}

} // namespace sbrt
