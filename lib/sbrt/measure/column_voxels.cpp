/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A column's property channels voxel by voxel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/column_voxels.hpp"

#include <cmath>

namespace sbrt {

std::vector<VoxelValues> column_voxels(const Model &model, const PropertyChannels &channels,
                                       GridCell cell)
{
    const Frame &frame = model.frame();
    const uint64_t index = model.cell_index(cell.row, cell.col);
    const ColumnSpan span = channels.span(index);
    std::vector<VoxelValues> out;
    if (span.size() == 0)
        return out;
    std::vector<ChannelValues> columns;
    for (size_t c = 0; c < channels.size(); ++c)
        columns.push_back(channels.column(c, index));
    // the material of each level from the stack, bottom up: an interval
    // covers the levels below its top (voxel tops are whole levels)
    std::vector<uint32_t> material(span.size(), EMPTY);
    const StackRange range = model.stack(index);
    model.intervals().visit([&](const auto *records) {
        double below = 0;
        for (uint64_t i = range.begin; i < range.end; ++i) {
            const double top = double(records[i].top);
            for (double level = std::max(below, double(span.lo));
                 level < std::min(top, double(span.hi)); ++level)
                material[size_t(level) - span.lo] = records[i].material;
            below = top;
        }
    });
    out.reserve(span.size());
    for (uint32_t level = span.hi; level-- > span.lo;) {
        VoxelValues v;
        v.level = level;
        v.bottom = map_height(frame, level);
        v.top = map_height(frame, level + 1.0);
        v.material = material[level - span.lo];
        for (size_t c = 0; c < channels.size(); ++c) {
            const ChannelInfo &info = channels.info(c);
            const float raw = columns[c][level - span.lo];
            v.values.push_back(info.is_fill(raw) ? NAN : info.physical(raw));
        }
        out.push_back(std::move(v));
    }
    return out;
}

} // namespace sbrt
