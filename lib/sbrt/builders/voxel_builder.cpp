/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Streaming voxel -> SBRT conversion
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/voxel_builder.hpp"

#include "util/error.hpp"

namespace sbrt {

namespace {

/// The frame, checked before anything is allocated for its cells.
const Frame &checked(const Frame &frame)
{
    frame.validate("VoxelStackBuilder");
    return frame;
}

} // namespace

VoxelStackBuilder::VoxelStackBuilder(const Frame &frame)
    : frame_(checked(frame)), open_class_(frame.cells(), NULL_CLASS),
      open_material_(frame.cells(), EMPTY)
{
}

void VoxelStackBuilder::close_run(uint32_t cell, uint32_t top)
{
    if (runs_.size() >= UINT32_MAX)
        fail("VoxelStackBuilder: more than 2^32-1 intervals");
    runs_.push_back({cell, open_material_[cell], top});
}

void VoxelStackBuilder::add_slice(const int32_t *classes)
{
    if (depth_ >= frame_.depths)
        fail("VoxelStackBuilder: more slices than the frame's ",
             frame_.depths, " depths");
    const uint32_t cells = uint32_t(frame_.cells());
    for (uint32_t c = 0; c < cells; ++c) {
        const int32_t id = classes[c];
        if (id == open_class_[c])
            continue;
        // a run of another class starts here: close the open one
        if (depth_ > 0)
            close_run(c, uint32_t(depth_));
        open_class_[c] = id;
        open_material_[c] = table_.material_of(id);
    }
    ++depth_;
}

Model VoxelStackBuilder::finish(const std::vector<Material> &legend)
{
    if (depth_ != frame_.depths)
        fail("VoxelStackBuilder: got ", depth_, " slices, the frame has ",
             frame_.depths);
    // close the topmost runs; a trailing EMPTY run is not stored
    const uint32_t cells = uint32_t(frame_.cells());
    for (uint32_t c = 0; c < cells; ++c)
        if (open_material_[c] != EMPTY)
            close_run(c, uint32_t(depth_));
    open_class_ = {};
    open_material_ = {};

    // stable counting sort of the runs by cell keeps each stack bottom-up
    std::vector<uint32_t> offsets(size_t(cells) + 1, 0);
    for (const Run &r : runs_)
        ++offsets[r.cell + 1];
    for (uint32_t c = 0; c < cells; ++c)
        offsets[c + 1] += offsets[c];
    // the stacks in the kind the depths allow (4 bytes an interval but
    // past 65535 layers)
    auto sorted = [&](auto records) {
        std::vector<uint32_t> next(offsets.begin(), offsets.end() - 1);
        using Record = typename decltype(records)::value_type;
        for (const Run &r : runs_)
            records[next[r.cell]++] = voxel_interval<Record>(r.material, r.top);
        return IntervalArray(std::move(records));
    };
    IntervalArray intervals = voxel_tops_fit_compact(frame_.depths)
                                  ? sorted(CompactIntervals(runs_.size()))
                                  : sorted(Intervals(runs_.size()));
    runs_ = {};

    return Model(frame_, table_.materials(legend), std::move(offsets),
                 std::move(intervals));
}

} // namespace sbrt
