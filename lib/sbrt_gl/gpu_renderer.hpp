/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GL counterpart of sbrt::Renderer: one prepared scene
 *            with its model on the GPU, rendered from any number of
 *            cameras, only the outputs coming back
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_RENDERER_HPP
#define SBRT_GL_GPU_RENDERER_HPP

#include "gpu_tracer.hpp"
#include "renderer.hpp"

namespace sbrt_gl {

/// What one frame on the GPU did.
struct GpuFrameReport {
    sbrt::RenderReport render; ///< the pipeline's bands and times
    GpuStats gpu;              ///< dispatches, read-back, rays over the budget
    /// Whether the GPU shaded (face normals, or kernel normals where the
    /// image's hits fit it), else the CPU did from the GPU's hits (for
    /// colours from property channels where the GPU does not make them:
    /// shaded_on_host).
    bool shaded_on_gpu = false;
    /// Shaded on the GPU: the host's time from when the GPU was done with
    /// the last band to the end of the frame (the sink's last band
    /// included), ms.
    double host_after_ms = 0;
};

/// \brief The prepared scene of `renderer` (model after hiding and
/// pruning, planes, pyramid; its shading, read at every frame) with the
/// model uploaded to the GPU of `context` once, at construction. Each
/// frame goes through the renderer's pipeline band by band: the GPU
/// traces, runs the first pass, finds the normals, drapes and lights, and
/// only the outputs asked for come back into the bands the sink takes;
/// kernel normals of an image whose hits do not fit the GPU are found on
/// the CPU from the GPU's hits. Holds
/// references to both arguments; the context must be current.
class GpuRenderer {
public:
    GpuRenderer(const GlContext &context, const sbrt::Renderer &renderer,
                const GpuOptions &options,
                ProgramCache cache = ProgramCache::from_environment());
    /// The same with GpuOptions::from_environment(layout).
    GpuRenderer(const GlContext &context, const sbrt::Renderer &renderer,
                sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo,
                ProgramCache cache = ProgramCache::from_environment());
    GpuRenderer(const GpuRenderer &) = delete;
    GpuRenderer &operator=(const GpuRenderer &) = delete;

    GpuFrameReport render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                          const sbrt::BandSink &sink, unsigned cpu_threads = 0);
    /// The same frame gathered into one image (tests, benchmarks).
    sbrt::Image render_image(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                             unsigned cpu_threads = 0);

    /// Whether the renderer's shading colours by voxel (property channels:
    /// property=, fade=) in a way the GPU does not (GpuTracer::paints: a
    /// property or fade of few whole values, face normals, no drape, no
    /// overlays, no value= output, a model small enough): the host shades
    /// then, at the GPU's hits.
    bool shaded_on_host(const sbrt::Outputs &outputs) const;
    /// Whether the GPU may colour by voxel at all (default yes): its words
    /// cover the whole model (every block decoded, made and uploaded at
    /// the first frame), which pays over a session's frames; the host's
    /// colouring at the GPU's hits decodes only the blocks rays reach.
    void paint_on_gpu(bool allowed) { paint_on_gpu_ = allowed; }
    /// Whether `camera`'s frame of `outputs` is shaded on the GPU with the
    /// renderer's shading as it is now.
    bool shades_on_gpu(const sbrt::Camera &camera, const sbrt::Outputs &outputs = {}) const;
    const GpuTracer &gpu() const { return gpu_; }
    GpuTracer &gpu() { return gpu_; }
    const sbrt::Renderer &renderer() const { return renderer_; }

private:
    const sbrt::Renderer &renderer_;
    GpuTracer gpu_;
    bool paint_on_gpu_ = true;
};

} // namespace sbrt_gl

#endif
