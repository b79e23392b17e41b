/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What the GPU tracer's files share (private to lib/sbrt_gl):
 *            its programs' sources per pass, timing, buffer sizes
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_INTERNAL_HPP
#define SBRT_GL_GPU_INTERNAL_HPP

#include <chrono>
#include <optional>
#include <vector>

#include "gl_objects.hpp"
#include "tracing/tracer.hpp"
#include "gpu/gpu_memory_layout.hpp"
#include "gpu_model.hpp"

namespace sbrt_gl {

using Clock = std::chrono::steady_clock;

/// Milliseconds since `start`.
double ms_since(Clock::time_point start);

/// `bytes`, or an error naming `what` where they exceed the GPU's largest
/// storage buffer (`limit`).
size_t checked_bytes(size_t bytes, size_t limit, const char *what);

/// A storage buffer for up to `rows` rows of `row_bytes`, within the GPU's
/// largest binding: the one in `buffer` where it is large enough.
void ensure_band_buffer(const GlApi &gl, std::optional<GlBuffer> &buffer, int rows,
                        size_t row_bytes, size_t max_block_bytes);

/// Whether `model`'s intervals go to the GPU a word each: held compact,
/// or read block by block where every block's are (its summaries' stats).
bool compact_on_gpu(const sbrt::Model &model);

/// What a program of the GPU path does.
enum class Pass : int {
    records,      ///< records.comp: hit records
    shade,        ///< shade.comp: the shaded outputs (SBRT_SHADE)
    kernel_depth, ///< kernel_depth.comp: the view depths
    kernel_normals, ///< kernel_normals.comp: the kernel normals
    kernel_across,  ///< kernel_across.comp: their sums along the rows
    kernel_shade, ///< kernel_shade.comp: kernel normals, shaded
    first_pass,   ///< first_pass.comp: the tiles' first-hit bounds
    /// shade.comp: the shaded outputs of the model and its boreholes
    /// over the listed tiles (SBRT_BOREHOLES, SBRT_TILE_LIST); the shade
    /// pass draws the model alone then
    shade_boreholes,
    /// tile_cull.comp: the tiles of a band the boreholes' pass draws
    cull_tiles
};

/// The sources of `pass` for the model's `form`, the form the tracer's model is held
/// in and its overlays (the shaded ray casting pass draws them:
/// common/overlays.glsl); with `drape`, a drape's colours among the
/// outputs (SBRT_DRAPE); with `paint`, the shading pass colours by voxel
/// (SBRT_PAINT: lib/sbrt/gpu/gpu_paint.hpp).
std::vector<const char *> pass_sources(Pass pass, const ModelForm &form,
                                       const sbrt::Tracer &tracer, bool drape = false,
                                       bool paint = false);

} // namespace sbrt_gl

#endif
