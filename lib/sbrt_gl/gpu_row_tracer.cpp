/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GPU as the streamed renderer's row tracer of one camera
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_row_tracer.hpp"

#include <algorithm>

#include "gpu/gpu_overlays.hpp"
#include "util/parallel.hpp"

namespace sbrt_gl {

std::optional<std::vector<sbrt::PixelRect>> cpu_pixels_of(const sbrt::Tracer &tracer,
                                                          const sbrt::Camera &camera)
{
    // overlays drawn with the model: the CPU traces their pixels where the
    // GPU writes hit records (the shading program draws boreholes itself;
    // drawn alone, boreholes and curtains are shaded on the GPU)
    if (tracer.has_overlays() && tracer.scene().draw_model)
        return sbrt::pixel_rects_of(tracer.overlay_boxes(), camera);
    return std::vector<sbrt::PixelRect>();
}

GpuRowTracer::GpuRowTracer(GpuTracer &gpu, const sbrt::Camera &camera, unsigned cpu_threads)
    : gpu_(gpu), camera_(camera), threads_(cpu_threads)
{
}

const std::optional<std::vector<sbrt::PixelRect>> &GpuRowTracer::cpu_pixels() const
{
    if (!cpu_rects_found_) {
        cpu_rects_ = cpu_pixels_of(gpu_.tracer(), camera_);
        cpu_rects_found_ = true;
    }
    return cpu_rects_;
}

template <typename PixelFunction>
void GpuRowTracer::for_cpu_pixels(int first, int count, const PixelFunction &f) const
{
    if (!any_cpu_pixels())
        return;
    const std::optional<std::vector<sbrt::PixelRect>> &rects = cpu_pixels(); // found: shared
    sbrt::for_each_row(first, first + count, threads_, [&](int row) {
        if (!rects) {
            for (int col = 0; col < camera_.cols(); ++col)
                f(row, col);
            return;
        }
        for (const auto &[c0, c1] : sbrt::row_spans(*rects, row))
            for (int col = c0; col <= c1; ++col)
                f(row, col);
    });
}

void GpuRowTracer::trace_rows(int first, int count, sbrt::Hit *out)
{
    gpu_.trace_rows(camera_, first, count, out, threads_, gpu_.loop_budget());
    const sbrt::Tracer &tracer = gpu_.tracer();
    const size_t cols = size_t(camera_.cols());
    for_cpu_pixels(first, count, [&](int row, int col) {
        tracer.trace_into(camera_.ray(row, col), 0, out[size_t(row - first) * cols + size_t(col)]);
    });
}

bool GpuRowTracer::shades_kernel_normals() const
{
    if (!(shading_ && shading_->normals == sbrt::Normals::kernel && gpu_.kernel_fits(camera_) &&
          !any_cpu_pixels()))
        return false;
    if (!kernel_prepared_)
        kernel_prepared_ = gpu_.prepare_kernel(camera_, *shading_);
    return *kernel_prepared_;
}

int GpuRowTracer::preferred_band_rows(int cols) const
{
    if (const int crowded = gpu_.crowded_band_rows(cols))
        return crowded;
    return std::max(1, (1 << 20) / std::max(cols, 1));
}

int GpuRowTracer::max_band_rows(int cols, const sbrt::Outputs &outputs) const
{
    return gpu_.max_band_rows(cols, outputs);
}

bool GpuRowTracer::shade_rows(int first, int count, const sbrt::Outputs &outputs,
                              sbrt::Band &band)
{
    if (!shading_)
        return false;
    if (shading_->normals == sbrt::Normals::kernel) {
        if (!shades_kernel_normals())
            return false;
        gpu_.shade_kernel_rows(camera_, first, count, *shading_, outputs, band, threads_);
        return true;
    }
    gpu_.shade_rows(camera_, first, count, *shading_, outputs, band, threads_);
    const sbrt::Tracer &tracer = gpu_.tracer();
    if (sbrt::gpu_overlay_mode(tracer) == sbrt::GpuOverlayMode::with_model)
        return true; // the boreholes' pass drew them
    if (!any_cpu_pixels())
        return true; // (no shader made for no pixel)
    const sbrt::PixelShader &shader = gpu_.host_shader(*shading_);
    for_cpu_pixels(first, count, [&](int row, int col) {
        sbrt::Hit hit;
        tracer.trace_into(camera_.ray(row, col), 0, hit);
        sbrt::shade_into_band(tracer, shader, camera_, hit, row, col, band);
    });
    return true;
}

} // namespace sbrt_gl
