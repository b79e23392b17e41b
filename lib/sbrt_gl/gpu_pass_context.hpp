/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What every pass of a GPU tracer reads and adds to (the GL,
 *            the resident model, the programs, the view block, the timer
 *            and the figures) and the paging of a paged model's
 *            dispatches, which the passes that walk the model share
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_PASS_CONTEXT_HPP
#define SBRT_GL_GPU_PASS_CONTEXT_HPP

#include <cstddef>

#include "gl_objects.hpp"
#include "gpu_model.hpp"
#include "gpu_stats.hpp"
#include "mapped_bands.hpp"
#include "program_set.hpp"
#include "gpu/gpu_layout.hpp"
#include "shading/shading.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

/// \brief The GPU tracer's parts that its passes (GpuFirstPass,
/// GpuRecordPass, GpuShadePass, GpuKernelPass) share, all owned by the
/// tracer: references only, so a pass holds the context by reference.
/// The context must be current.
struct PassContext {
    const GlApi &gl;
    const sbrt::Tracer &tracer;
    GpuModel &model;        ///< what stays on the GPU for the scene
    ProgramSet &programs;   ///< every pass's programs
    GlBuffer &view;         ///< the view block (uniform binding 0)
    PassTimer &timer;       ///< GpuStats::pass_ms
    GpuStats &stats;
    size_t max_block_bytes; ///< the GPU's largest storage buffer binding
    /// GpuOptions::crowded_band_pixels (at least 1)
    int crowded_band_pixels;

    /// `view` over rows [first, first + count) uploaded to the view block.
    void upload_view(sbrt::GpuView &view, int first, int count) const;
    /// `pass`'s program (in use) over width x height invocations in 8 x 8
    /// work groups, timed as `pass`.
    void dispatch(Pass pass, int width, int height) const;
    /// The program of `pass` used and dispatched over width x height
    /// invocations (pixels of the whole image, or the first pass's tiles),
    /// its buffers bound; a barrier after.
    void run_pass(Pass pass, int width, int height) const;
    /// The shading program of `pass` (shade, shade_boreholes or
    /// kernel_shade) for `shading` (with its drape; colours by voxel in the
    /// shade pass alone), built when first needed.
    GlComputeProgram &shading_program(const sbrt::Shading &shading, Pass pass) const;

    /// A paged model: whether blocks that the dispatches so far found
    /// missing were brought up (their rays then go again); adds to
    /// GpuStats::page_ms and page_passes.
    bool brought_wanted_blocks() const;
    /// A paged model's band as band_again goes over it: the pages that
    /// had found no room in the atlas before it began, and whether it began
    /// the atlas's frame again.
    struct BandPaging {
        uint64_t no_room_before = 0;
        bool restarted = false;
    };
    BandPaging begin_band() const;
    /// Whether to dispatch a paged model's band again: its missed pages
    /// came up, or (once a band) some found no room since it began, and
    /// the earlier bands' pages may now go for its own
    /// (GpuPageAtlas::begin_band_again).
    bool band_again(BandPaging &band) const;
    /// The rows `cols` wide of a band where a paged model's atlas is
    /// crowded (crowded_band_pixels); else 0.
    int crowded_band_rows(int cols) const;
};

} // namespace sbrt_gl

#endif
