/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The two ways the GPU holds a model (section 4.2 of Graciano
 *            et al.): 5-SSBO, an offsets buffer and an intervals buffer
 *            read as arrays; 1-Textures, an index texture over the grid
 *            (first interval, count) and the intervals packed row by row
 *            into a 2D texture. Their texels, and their memory and waste
 *            (Table 3 of the paper). Both read the model's compact form
 *            where it has one: 4-byte intervals, and (5-SSBO) the stack
 *            index as counts and group offsets
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GPU_MEMORY_LAYOUT_HPP
#define SBRT_GPU_MEMORY_LAYOUT_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

enum class GpuLayout { ssbo, textures };

/// "ssbo" or "textures" (the names of r3.sbrt.render's layout=).
GpuLayout parse_gpu_layout(const std::string &name);
const char *gpu_layout_name(GpuLayout layout);

/// \brief What a layout takes on the GPU for a model: the index (offsets
/// or index texture) and the intervals, each with the bytes that hold
/// nothing (texels past the last interval).
struct GpuMemory {
    uint64_t index_bytes = 0, interval_bytes = 0, waste_bytes = 0;
    int texture_cols = 0, texture_rows = 0; ///< intervals texture (textures)
    uint64_t total() const { return index_bytes + interval_bytes; }
};

/// Bytes per texel of the index texture (GL_RG32UI: first, count) and of
/// the intervals texture of wide intervals; compact ones take GL_R32UI,
/// 4 bytes, as in the intervals buffer.
constexpr int TEXEL_BYTES = 8;

/// Most intervals a GPU layout addresses (32-bit indices in the shaders).
constexpr uint64_t MAX_GPU_INTERVALS = UINT32_MAX;

/// Size of the intervals texture for `intervals` intervals: as square as
/// the largest texture side allows, at most one row partly empty; throws
/// where even max_side x max_side texels are too few.
void interval_texture_size(uint64_t intervals, int max_side, int &cols, int &rows);

/// Memory of `layout` for `model` on a GPU whose textures are at most
/// max_side texels wide and high; throws with what does not fit.
GpuMemory gpu_memory(const Model &model, GpuLayout layout, int max_side);

/// Index texture, cols x rows texels, row 0 the northernmost: per cell its
/// first interval and its count.
std::vector<uint32_t> index_texels(const Model &model);
/// Intervals texture, cols x rows texels, row-major: per interval its
/// material and the bits of its top (float), or one word (material | top
/// << 16) where the intervals are compact; the rest zero.
std::vector<uint32_t> interval_texels(const Model &model, int cols, int rows);

/// 5-SSBO's group offsets: the first interval of every group of
/// StackIndex::GROUP cells (32 bits: MAX_GPU_INTERVALS).
std::vector<uint32_t> group_offset_words(const Model &model);

} // namespace sbrt

#endif
