/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GL counterpart of sbrt::Renderer
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_renderer.hpp"

#include <chrono>

#include "gpu_row_tracer.hpp"

namespace sbrt_gl {

GpuRenderer::GpuRenderer(const GlContext &context, const sbrt::Renderer &renderer,
                         const GpuOptions &options, ProgramCache cache)
    : renderer_(renderer), gpu_(context, renderer.tracer(), options, std::move(cache))
{
}

GpuRenderer::GpuRenderer(const GlContext &context, const sbrt::Renderer &renderer,
                         sbrt::GpuLayout layout, ProgramCache cache)
    : GpuRenderer(context, renderer, GpuOptions::from_environment(layout), std::move(cache))
{
}

bool GpuRenderer::shaded_on_host(const sbrt::Outputs &outputs) const
{
    const sbrt::Shading &shading = renderer_.shading();
    return (shading.property || shading.fade) &&
           (!paint_on_gpu_ || !gpu_.paints(shading, outputs));
}

bool GpuRenderer::shades_on_gpu(const sbrt::Camera &camera, const sbrt::Outputs &outputs) const
{
    const sbrt::Shading &shading = renderer_.shading();
    if (shaded_on_host(outputs))
        return false;
    if (shading.normals == sbrt::Normals::face)
        return true;
    // kernel normals: where the image's hits fit and no pixel comes from the CPU
    const auto cpu_pixels = cpu_pixels_of(renderer_.tracer(), camera);
    return gpu_.kernel_fits(camera) && cpu_pixels && cpu_pixels->empty();
}

GpuFrameReport GpuRenderer::render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                                   const sbrt::BandSink &sink, unsigned cpu_threads)
{
    GpuFrameReport report;
    gpu_.begin_frame();
    GpuRowTracer rows(gpu_, camera, cpu_threads);
    // where kernel normals cannot be found on the GPU the renderer finds
    // them from the GPU's hits (it never asks the GPU to shade then)
    const bool on_host = shaded_on_host(outputs);
    rows.shade_on_gpu(on_host ? nullptr : &renderer_.shading());
    report.shaded_on_gpu =
        !on_host &&
        (renderer_.shading().normals == sbrt::Normals::face || rows.shades_kernel_normals());
    report.render = renderer_.render(camera, outputs, sink, &rows);
    const auto done = std::chrono::steady_clock::now();
    if (report.shaded_on_gpu && gpu_.last_band_done() <= done)
        report.host_after_ms =
            std::chrono::duration<double, std::milli>(done - gpu_.last_band_done()).count();
    report.gpu = gpu_.stats();
    report.gpu.pass_ms = gpu_.take_pass_ms();
    return report;
}

sbrt::Image GpuRenderer::render_image(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                                      unsigned cpu_threads)
{
    sbrt::Image image = sbrt::empty_image(camera, outputs);
    render(camera, outputs, [&](const sbrt::Band &band) { sbrt::gather_band(band, image); },
           cpu_threads);
    return image;
}

} // namespace sbrt_gl
