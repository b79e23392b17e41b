/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colours by voxel on the GPU (issue 29): the C++ side of the
 *            `buffer Paint` of shaders/common/shade.glsl (SBRT_PAINT). A
 *            property whose values are few whole numbers (a sum of
 *            GeoTOP's percentages), or an uncertainty fade by such a
 *            channel, goes up as one colour entry per voxel and a table
 *            of the entries' colours; the shader finds a hit's voxel as
 *            voxel_of_hit does and its colour by two look-ups
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GPU_PAINT_HPP
#define SBRT_GPU_PAINT_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "output/band.hpp"
#include "shading/shading.hpp"
#include "tracing/tracer.hpp"

namespace sbrt {

/// A voxel's entry: where it has no value (the property's no-value
/// colour, the fade's class colour), and where its value lies outside the
/// file's stated range (not trusted: the shader sends the pixel to the
/// host, which colours it from the value).
constexpr uint32_t GPU_PAINT_NONE = 0xffff, GPU_PAINT_OUTSIDE = 0xfffe;
/// Most colours of a fade's table (classes x fade values).
constexpr size_t GPU_PAINT_MAX_COLOURS = size_t(1) << 20;
/// Most voxels whose entries go up (128 MiB of them, made in about a
/// second on 16 cores): a larger model is coloured on the host at the
/// GPU's hits, which decodes only the blocks that rays reach.
constexpr uint64_t GPU_PAINT_MAX_VOXELS = uint64_t(1) << 26;

/// Whether the GPU can colour `shading`'s property or fade at `tracer`'s
/// hits with `outputs`: one of them (not both), its values few whole
/// numbers, face normals, no drape, no overlays, no value= output, a
/// model of fewer than 65,536 levels and channels of at most
/// GPU_PAINT_MAX_VOXELS voxels. Elsewhere the host colours the hits.
bool gpu_paints(const Tracer &tracer, const Shading &shading, const Outputs &outputs);
/// The most bytes make_gpu_paint's words take (where gpu_paints holds).
uint64_t gpu_paint_bytes(const Tracer &tracer, const Shading &shading);

/// `buffer Paint` (std430 uint words) for `shading` over `tracer`'s model
/// (gpu_paints must hold): a head of 4 words (where the entries start,
/// where the colours start, fade values + 1 or 0 for a property, the
/// colour of GPU_PAINT_NONE); per cell (rows from the north) the index of
/// its span's first entry and lo | hi << 16 (empty where the prepared
/// model has no stack there: those blocks are not decoded); the entries,
/// two 16-bit ones a word (the first in the low half); the colours as
/// float bits r, g, b (0..255, before lighting): a property's per value,
/// then its no-value colour; a fade's per class of the tracer's model,
/// per fade value, then the class's own colour. Decodes on `threads`.
std::vector<uint32_t> make_gpu_paint(const Tracer &tracer, const Shading &shading,
                                     unsigned threads = 0);

/// What make_gpu_paint's words depend on beyond the model: equal keys,
/// equal words (a GPU keeps its upload while the key stays).
std::string gpu_paint_key(const Shading &shading);

} // namespace sbrt

#endif
