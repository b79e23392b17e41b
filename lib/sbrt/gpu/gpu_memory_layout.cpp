/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   GPU memory layouts of a model: texels, memory, waste
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_memory_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "util/error.hpp"

namespace sbrt {

GpuLayout parse_gpu_layout(const std::string &name)
{
    if (name == "ssbo")
        return GpuLayout::ssbo;
    if (name == "textures")
        return GpuLayout::textures;
    fail("GPU layout '", name, "' is neither ssbo nor textures");
}

const char *gpu_layout_name(GpuLayout layout)
{
    return layout == GpuLayout::ssbo ? "ssbo" : "textures";
}

void interval_texture_size(uint64_t intervals, int max_side, int &cols, int &rows)
{
    const uint64_t side = uint64_t(max_side);
    if (intervals > side * side)
        fail("the model's ", intervals, " intervals do not fit a ", max_side, " x ",
             max_side, " texture, this GPU's largest: use layout=ssbo");
    const uint64_t n = std::max<uint64_t>(intervals, 1);
    uint64_t c = uint64_t(std::ceil(std::sqrt(double(n))));
    while (c * c < n) // sqrt of a large integer may round down
        ++c;
    c = std::min(c, side);
    cols = int(c);
    rows = int((n + c - 1) / c);
}

namespace {

/// Throws where the GPU's 32-bit indices cannot address `n` intervals.
void check_gpu_intervals(uint64_t n)
{
    if (n > MAX_GPU_INTERVALS)
        fail("the model's ", n, " intervals exceed the ", MAX_GPU_INTERVALS,
             " a GPU layout addresses: use backend=cpu");
}

} // namespace

GpuMemory gpu_memory(const Model &model, GpuLayout layout, int max_side)
{
    if (model.is_paged())
        fail("GPU upload: the model is paged (its blocks decoded as the CPU's rays reach "
             "them); the GPU takes a model decoded whole");
    const Frame &f = model.frame();
    const uint64_t n = model.intervals().size();
    check_gpu_intervals(n);
    const unsigned record = model.intervals().record_bytes();
    GpuMemory m;
    if (layout == GpuLayout::ssbo) {
        const StackIndex &index = model.index();
        m.index_bytes = index.group_offsets().size() * sizeof(uint32_t) + index.count_data_bytes();
        m.interval_bytes = n * record;
        return m;
    }
    if (f.cols > max_side || f.rows > max_side)
        fail("the grid of ", f.cols, " x ", f.rows, " cells exceeds this GPU's largest "
             "texture (", max_side, " x ", max_side, "): use layout=ssbo");
    interval_texture_size(n, max_side, m.texture_cols, m.texture_rows);
    m.index_bytes = f.cells() * TEXEL_BYTES;
    m.interval_bytes = uint64_t(m.texture_cols) * m.texture_rows * record;
    m.waste_bytes = m.interval_bytes - n * record;
    return m;
}

std::vector<uint32_t> index_texels(const Model &model)
{
    const Frame &f = model.frame();
    std::vector<uint32_t> texels(2 * f.cells());
    // cell_index(row, col) runs row-major from the north, as the texture
    for (uint64_t cell = 0; cell < f.cells(); ++cell) {
        const StackRange stack = model.stack(cell);
        texels[2 * cell] = uint32_t(stack.begin); // gpu_memory checked the count
        texels[2 * cell + 1] = uint32_t(stack.size());
    }
    return texels;
}

std::vector<uint32_t> interval_texels(const Model &model, int cols, int rows)
{
    const IntervalArray &intervals = model.intervals();
    if (uint64_t(cols) * uint64_t(rows) < intervals.size())
        fail("interval texture of ", cols, " x ", rows, " texels is too small");
    if (intervals.is_compact()) {
        std::vector<uint32_t> texels(size_t(cols) * rows, 0);
        const CompactInterval *records = intervals.compact_data();
        for (size_t j = 0; j < intervals.size(); ++j)
            texels[j] = uint32_t(records[j].material) | uint32_t(records[j].top) << 16;
        return texels;
    }
    std::vector<uint32_t> texels(2 * size_t(cols) * rows, 0);
    for (size_t j = 0; j < intervals.size(); ++j) {
        const Interval iv = intervals[j];
        texels[2 * j] = iv.material;
        std::memcpy(&texels[2 * j + 1], &iv.top, sizeof(float));
    }
    return texels;
}

std::vector<uint32_t> group_offset_words(const Model &model)
{
    const std::vector<uint64_t> &offsets = model.index().group_offsets();
    check_gpu_intervals(model.index().total());
    return std::vector<uint32_t>(offsets.begin(), offsets.end());
}

} // namespace sbrt
