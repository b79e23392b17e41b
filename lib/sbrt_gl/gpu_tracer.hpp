/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   First hits of every pixel on the GPU: the model in std430
 *            SSBOs, the compute shader shaders/raycast.comp, bands of rows
 *            that fit the GPU's buffer limit, and the exact CPU tracer for
 *            the rays the shader flags as over its loop budget
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_TRACER_HPP
#define SBRT_GL_GPU_TRACER_HPP

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "gl_api.hpp"
#include "gl_objects.hpp"
#include "gpu_layout.hpp"
#include "cpu_tracing.hpp"
#include "gpu_memory_layout.hpp"
#include "hit_image.hpp"

namespace sbrt_gl {

/// Figures of the last trace_image call (or of the trace_rows calls since
/// reset_stats).
struct GpuStats {
    double upload_ms = 0;   ///< shader compile and model upload
    double trace_ms = 0;    ///< dispatches until the GPU is done
    double readback_ms = 0; ///< hit records back and decoded
    size_t over_budget = 0; ///< rays traced again on the CPU
    int bands = 0;
};

class GpuTracer {
public:
    /// Needs the context current on this thread; uploads the model in
    /// `layout`.
    GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
              sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo);

    sbrt::HitImage trace_image(const sbrt::Camera &camera,
                               unsigned cpu_threads = 0,
                               uint32_t loop_budget = sbrt::GPU_LOOP_BUDGET);

    /// Hits of rows [first, first + count) of `camera`'s image (the rays
    /// of the whole image), row-major into `out`; records decoded on
    /// `cpu_threads` threads. Adds to stats().
    void trace_rows(const sbrt::Camera &camera, int first, int count, sbrt::Hit *out,
                    unsigned cpu_threads = 0,
                    uint32_t loop_budget = sbrt::GPU_LOOP_BUDGET);
    void reset_stats();

    std::string gl_version() const;
    std::string gl_renderer() const;
    const GpuStats &stats() const { return stats_; }
    /// What the model takes on the GPU in its layout.
    const sbrt::GpuMemory &memory() const { return memory_; }
    sbrt::GpuLayout layout() const { return layout_; }
    /// Bytes of the empty-space pyramid on the GPU.
    size_t pyramid_bytes() const { return pyramid_.bytes(); }
    const GlApi &gl() const { return gl_; }
    GLuint program() const { return program_.name(); }

private:
    std::chrono::steady_clock::time_point created_; ///< times the upload
    const sbrt::Tracer &tracer_;
    GlApi gl_;
    size_t max_block_bytes_;
    sbrt::GpuLayout layout_;
    sbrt::GpuMemory memory_;
    GlComputeProgram program_;
    /// the model: two buffers (ssbo) or two textures (textures)
    std::optional<GlBuffer> offsets_, intervals_;
    std::optional<GlUintTexture> index_texture_, interval_texture_;
    GlBuffer materials_, view_;
    GlBuffer pyramid_; ///< empty-space skipping (levels() 0: off)
    std::optional<GlBuffer> band_; ///< the hit records of a band of rows
    std::vector<sbrt::GpuPixelHit> records_;
    GpuStats stats_;
};

/// \brief The GPU as the streamed renderer's row tracer of one camera.
class GpuRowTracer : public sbrt::RowTracer {
public:
    GpuRowTracer(GpuTracer &gpu, const sbrt::Camera &camera, unsigned cpu_threads = 0)
        : gpu_(gpu), camera_(camera), threads_(cpu_threads)
    {
    }
    void trace_rows(int first, int count, sbrt::Hit *out) override
    {
        gpu_.trace_rows(camera_, first, count, out, threads_);
    }

private:
    GpuTracer &gpu_;
    const sbrt::Camera &camera_;
    unsigned threads_;
};

} // namespace sbrt_gl

#endif
