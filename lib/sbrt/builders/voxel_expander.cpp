/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   SBRT -> voxels
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/voxel_expander.hpp"

#include <cmath>

#include "util/error.hpp"

namespace sbrt {

VoxelExpander::VoxelExpander(const Model &model, const Frame &target)
    : model_(model), target_(target), source_cell_(target.cells(), -1),
      cursor_(target.cells(), 0), end_(target.cells(), 0)
{
    target_.validate("VoxelExpander");
    const Frame &src = model.frame();
    // map the centre of every target column to the source cell holding it
    for (int row = 0; row < target_.rows; ++row) {
        const double y = target_.north - (row + 0.5) * target_.ns_res();
        const double src_row = std::floor((src.north - y) / src.ns_res());
        for (int col = 0; col < target_.cols; ++col) {
            const double x = target_.west + (col + 0.5) * target_.ew_res();
            const double src_col = std::floor((x - src.west) / src.ew_res());
            const uint64_t t = uint64_t(row) * target_.cols + col;
            if (src_row < 0 || src_row >= src.rows || src_col < 0 ||
                src_col >= src.cols)
                continue;
            source_cell_[t] = int64_t(model.cell_index(int(src_row), int(src_col)));
            const StackRange stack = model.stack(uint64_t(source_cell_[t]));
            cursor_[t] = stack.begin;
            end_[t] = stack.end;
        }
    }
}

void VoxelExpander::next_slice(int32_t *classes)
{
    if (depth_ >= target_.depths)
        fail("VoxelExpander: all ", target_.depths, " slices were produced");
    const Frame &src = model_.frame();
    const double z = target_.bottom + (depth_ + 0.5) * target_.tb_res();
    const double local = src.local_z(z);
    const auto &intervals = model_.intervals();
    const auto &materials = model_.materials();
    const uint64_t cells = target_.cells();
    for (uint64_t t = 0; t < cells; ++t) {
        classes[t] = NULL_CLASS;
        if (source_cell_[t] < 0 || local < 0)
            continue;
        const uint64_t end = end_[t];
        uint64_t &i = cursor_[t];
        while (i < end && !(local < intervals[i].top))
            ++i;
        if (i < end && intervals[i].material != EMPTY)
            classes[t] = materials[intervals[i].material].id;
    }
    ++depth_;
}

} // namespace sbrt
