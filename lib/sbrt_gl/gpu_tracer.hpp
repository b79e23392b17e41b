/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   First hits of every pixel on the GPU: the resident model
 *            (GpuModel), the programs (ProgramSet), the view block and the
 *            figures, composing the passes (first pass, hit records,
 *            shading, boreholes, kernel normals: one class each)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_TRACER_HPP
#define SBRT_GL_GPU_TRACER_HPP

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gl_api.hpp"
#include "gl_objects.hpp"
#include "gpu_model.hpp"
#include "gpu_options.hpp"
#include "gpu_borehole_pass.hpp"
#include "gpu_first_pass.hpp"
#include "gpu_kernel_pass.hpp"
#include "gpu_pass_context.hpp"
#include "gpu_record_pass.hpp"
#include "gpu_shade_pass.hpp"
#include "gpu_shading_inputs.hpp"
#include "gpu_stats.hpp"
#include "mapped_bands.hpp"
#include "program_set.hpp"
#include "gpu/gpu_layout.hpp"
#include "tracing/cpu_tracing.hpp"
#include "gpu/gpu_memory_layout.hpp"
#include "gpu/gpu_overlays.hpp"
#include "shading/shading.hpp"
#include "tracing/hit_image.hpp"

namespace sbrt_gl {

/// What a program of the GPU path does (gpu_internal.hpp).
enum class Pass : int;

/// \brief The GPU path over one scene: the resident model (GpuModel), the
/// programs (ProgramSet), the view block, the timer and the figures, and
/// one object a pass, each owning its buffers (GpuFirstPass, GpuRecordPass,
/// GpuShadePass, BoreholePass, GpuKernelPass), which trace_rows,
/// shade_rows, prepare_kernel and shade_kernel_rows compose; the passes
/// share the parts the tracer owns through a PassContext.
class GpuTracer {
public:
    /// Needs the context current on this thread; uploads the model in
    /// `options.layout`. Programs are compiled when first used, or loaded
    /// from `cache` (by default where SBRT_PROGRAM_CACHE or the user's
    /// cache directory says).
    GpuTracer(const GlContext &context, const sbrt::Tracer &tracer, const GpuOptions &options,
              ProgramCache cache = ProgramCache::from_environment());
    /// The same with GpuOptions::from_environment(layout).
    GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
              sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo,
              ProgramCache cache = ProgramCache::from_environment());

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

    /// Rows [first, first + count) of `camera`'s image traced and shaded on
    /// the GPU (face normals, a drape or none: make_gpu_shade; the drape
    /// goes up once, with its first band) into a mapped buffer (MappedBands)
    /// that `band` then views: RGB and the outputs of `outputs`, nothing
    /// else; rays over the loop budget are traced and shaded again on the
    /// host. The next band is dispatched before this one is waited for.
    /// Adds to stats().
    /// Boreholes drawn with the model are shaded in a second pass over the
    /// 8 x 8 tiles their pixels lie in (listed by the GPU, tile_cull.comp),
    /// the model alone in the first, skipping with the model's own pyramid.
    void shade_rows(const sbrt::Camera &camera, int first, int count,
                    const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                    sbrt::Band &band, unsigned cpu_threads = 0);
    /// The most rows `cols` wide of `outputs` that one shaded band holds.
    int max_band_rows(int cols, const sbrt::Outputs &outputs) const;
    /// The rows `cols` wide of a band: where a paged model's atlas is
    /// crowded, as GpuOptions::crowded_band_pixels says; else 0 (as many
    /// as fill the GPU).
    int crowded_band_rows(int cols) const { return passes_.crowded_band_rows(cols); }
    /// A new frame: bands dispatched ahead for the last one are dropped.
    void begin_frame();
    /// GL time queries around every pass (GpuStats::pass_ms), or none.
    void time_passes(bool on) { timer_.enable(on); }
    /// The GPU time of each pass since the frame began (waits for the
    /// queries; empty where not timed).
    std::vector<double> take_pass_ms();
    /// When the GPU was found done with the last band shaded.
    std::chrono::steady_clock::time_point last_band_done() const { return shade_.last_done(); }
    /// Whether kernel normals of `camera`'s image can be found on the GPU:
    /// the hit records of the whole image fit one storage buffer (and the
    /// camera is not a window of a larger image), and the GPU writes them
    /// (not for boreholes and curtains alone).
    bool kernel_fits(const sbrt::Camera &camera) const { return kernel_.fits(camera); }
    /// Kernel normals on the GPU, first for a camera: traces the hit records
    /// of its whole image and their view depths, kept on the GPU. False
    /// where a paged model's blocks found no room in the atlas, or its
    /// atlas is crowded (the whole image's would not fit): records are
    /// missing, and the kernel normals must be found on the host.
    bool prepare_kernel(const sbrt::Camera &camera, const sbrt::Shading &shading);
    /// Then rows [first, first + count): kernel normals (shading.kernel,
    /// smoothed by shading.smooth) from the depths, shaded as shade_rows
    /// does.
    void shade_kernel_rows(const sbrt::Camera &camera, int first, int count,
                           const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                           sbrt::Band &band, unsigned cpu_threads = 0);
    /// Whether the shading pass colours `shading`'s property or fade for
    /// `outputs` (sbrt::gpu_paints, in one storage buffer of this GL).
    bool paints(const sbrt::Shading &shading, const sbrt::Outputs &outputs) const;
    /// The host's shader of `shading` for the pixels it traces and shades
    /// (kept while the shading stays as it was).
    const sbrt::PixelShader &host_shader(const sbrt::Shading &shading)
    {
        return shade_.host_shader(shading);
    }
    /// The loop budget of the shaded bands and the kernel passes
    /// (GpuOptions::loop_budget: by default llvmpipe's GPU_LOOP_BUDGET,
    /// none on a GPU).
    uint32_t loop_budget() const { return loop_budget_; }
    /// Whether the shading pass writes bands into GPU memory, copied to the
    /// host by the GPU (GpuOptions::bands: by default on a GPU).
    bool staged_bands() const { return shade_.staged(); }
    /// The shading program (compiled by the first shade_rows; the one with
    /// the drape where there was one), or 0.
    GLuint shade_program() const
    {
        const GlComputeProgram *p = shading_program_built();
        return p ? p->name() : 0;
    }
    /// The kernel normals' shading program (compiled by the first
    /// shade_kernel_rows), or 0.
    GLuint kernel_program() const
    {
        const GlComputeProgram *draped = programs_.built(Pass::kernel_shade, {true, false});
        const GlComputeProgram *p = draped ? draped : programs_.built(Pass::kernel_shade);
        return p ? p->name() : 0;
    }

    const sbrt::Tracer &tracer() const { return tracer_; }
    std::string gl_version() const;
    std::string gl_renderer() const;
    const GpuStats &stats() const
    {
        stats_.programs_ms = programs_.build_ms();
        return stats_;
    }
    /// What stays on the GPU for the scene.
    const GpuModel &model() const { return model_; }
    /// What the model takes on the GPU in its layout.
    const sbrt::GpuMemory &memory() const { return model_.memory(); }
    sbrt::GpuLayout layout() const { return model_.layout(); }
    /// Bytes of the empty-space pyramid on the GPU.
    size_t pyramid_bytes() const { return model_.pyramid_bytes(); }
    const GlApi &gl() const { return gl_; }
    /// The program that writes hit records (compiled when first asked for).
    GLuint program() const { return record_program().name(); }
    /// The first pass's bounds of the last camera traced, per tile
    /// row-major (read back; tests).
    std::vector<float> tile_starts() const { return first_pass_.tile_starts(); }
    /// Whether the shading program (shade_program) came from the cache.
    bool shade_program_from_cache() const
    {
        const GlComputeProgram *p = shading_program_built();
        return p && p->from_cache();
    }

private:
    const GlComputeProgram &record_program() const { return programs_.get(Pass::records); }
    /// The shading pass's program built (colours by voxel, else with a
    /// drape, else plain), or null.
    const GlComputeProgram *shading_program_built() const;
    /// Binds the model (GpuModel::bind), the first pass's bounds and the
    /// view block.
    void bind_model() const;

    std::chrono::steady_clock::time_point created_; ///< times the upload
    std::chrono::steady_clock::time_point frame_start_; ///< begin_frame
    const sbrt::Tracer &tracer_;
    GlApi gl_;
    size_t max_block_bytes_;
    GpuModel model_; ///< what stays on the GPU for the scene
    /// every pass's programs; mutable: the hit records' program is built
    /// when first used
    mutable ProgramSet programs_;
    GpuShadingInputs shading_inputs_; ///< the Shade block, a drape, colours by voxel
    GlBuffer view_; ///< the view block
    PassTimer timer_;
    mutable GpuStats stats_; ///< mutable: stats() adds the programs' time
    uint32_t loop_budget_;
    /// what the passes share: the members above, and a paged model's paging
    PassContext passes_;
    GpuFirstPass first_pass_; ///< the tiles' first-hit bounds
    GpuRecordPass records_;   ///< hit records read back
    GpuShadePass shade_;      ///< shaded bands, mapped
    BoreholePass boreholes_;  ///< boreholes drawn with the model
    GpuKernelPass kernel_;    ///< kernel normals
};

} // namespace sbrt_gl

#endif
