/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   How the GPU path runs on the GL it meets: the model's layout,
 *            where the shading pass writes a band, the loop budget; by
 *            default as that GL calls for (a GPU or llvmpipe), settable so
 *            that llvmpipe runs a GPU's branches too (tests)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_OPTIONS_HPP
#define SBRT_GL_GPU_OPTIONS_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "gpu/gpu_layout.hpp"
#include "gpu/gpu_memory_layout.hpp"

namespace sbrt_gl {

class GpuPageAtlas;

/// Where the shading pass writes a band (MappedBands).
enum class BandStaging {
    automatic, ///< staged on a GPU, direct on a software renderer
    staged,    ///< into GPU memory, copied into the mapped buffer by the GPU
    direct     ///< into the mapped buffer itself
};

/// A loop budget without a bound: a ray runs to its end.
constexpr uint32_t UNBOUNDED_LOOP_BUDGET = UINT32_MAX;

/// The atlas of a paged model, unless asked otherwise: 1 GiB.
constexpr uint64_t DEFAULT_PAGE_BUDGET = uint64_t(1) << 30;

/// \brief The choices of a GpuTracer (and GpuRenderer) made at its
/// construction. The defaults are what the GL met calls for.
struct GpuOptions {
    sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo;
    BandStaging bands = BandStaging::automatic;
    /// Loop iterations a ray of the shaded bands and of the kernel passes
    /// may take before the host traces it again; unset: llvmpipe's
    /// (sbrt::GPU_LOOP_BUDGET: llvmpipe ends an invocation after 65,535),
    /// UNBOUNDED_LOOP_BUDGET on a GPU.
    std::optional<uint32_t> loop_budget;
    /// GPU memory for a model read block by block: its empty-space
    /// pyramid (at most half), its columns' top intervals (where they take
    /// at most half of what is left) and the atlas of the blocks its rays
    /// reach (GpuPageAtlas, within the GPU's largest storage buffer).
    uint64_t page_budget_bytes = DEFAULT_PAGE_BUDGET;
    /// Where a paged model's atlas is kept between the tracers of its
    /// scenes (a view server's: a stratum hidden keeps the blocks up),
    /// taken over where it serves the model; null: each tracer its own.
    std::shared_ptr<GpuPageAtlas> *kept_atlas = nullptr;
    /// A paged model's columns (their top intervals and ranges) in pages
    /// of their own, with the pyramid from this level on, even where they
    /// fit whole (tests, measurements); 0: where they do not fit.
    int column_pages_from_level = 0;
    /// Pixels of a band where a paged model's atlas is crowded (its blocks
    /// found no room, GpuPageAtlas::crowded): bands whose blocks fit where
    /// a frame's do not. Else bands of a million pixels fill a GPU.
    int crowded_band_pixels = 1 << 16;

    /// The defaults in `layout`, the bands as SBRT_GPU_BANDS says where it
    /// is set ("staged" or "direct": measurements, device_run.sh); the one
    /// place that reads it.
    static GpuOptions from_environment(sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo);
};

/// Whether bands are staged on a GL whose GL_RENDERER is `renderer`.
bool staged_bands(const GpuOptions &options, const std::string &renderer);
/// The loop budget on a GL whose GL_RENDERER is `renderer`.
uint32_t loop_budget(const GpuOptions &options, const std::string &renderer);

} // namespace sbrt_gl

#endif
