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
    if (cells_done() >= frame_.cells())
        fail("ColumnStackBuilder: more columns than the frame's ",
             frame_.cells(), " cells");
    const int depths = frame_.depths;
    size_t solid_end = intervals_.size(); // after the last non-EMPTY run
    int z = 0;
    while (z < depths) {
        const int32_t id = classes[z];
        int top = z + 1;
        while (top < depths && classes[top] == id)
            ++top;
        const uint32_t material = table_.material_of(id);
        intervals_.push_back({material, float(top)});
        if (material != EMPTY)
            solid_end = intervals_.size();
        z = top;
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
