/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Image-space kernel normals on the GPU (shaders/kernel_*.comp):
 *            the whole image's hit records and view depths kept on the
 *            GPU, then the kernel normals and shading of each band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_tracer.hpp"

#include "gpu_internal.hpp"
#include "util/error.hpp"

namespace sbrt_gl {

bool GpuTracer::kernel_fits(const sbrt::Camera &camera) const
{
    // the GPU writes no hit records of boreholes and curtains alone
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    return tracer_.scene().draw_model && !camera.is_window() &&
           pixels * sizeof(sbrt::GpuPixelHit) <= max_block_bytes_;
}

bool GpuTracer::prepare_kernel(const sbrt::Camera &camera, const sbrt::Shading &shading)
{
    if (!kernel_fits(camera))
        sbrt::fail("kernel normals on the GPU: the image's hit records do not fit one "
                   "storage buffer, or the GPU does not write them (boreholes and curtains "
                   "alone, a window of an image)");
    const int rows = camera.rows(), cols = camera.cols();
    const size_t pixels = size_t(rows) * size_t(cols);
    // 1. the hit records of the whole image, kept on the GPU
    sbrt::GpuView view = traced_view(camera, loop_budget_);
    view.options[2] = 0;
    view.options[3] = uint32_t(rows);
    bind_model();
    view_.upload(&view, sizeof view);
    kernel_buffers_.bind_image_records(pixels);
    const auto start = Clock::now();
    const GpuPageAtlas *pages = model_.pages();
    const uint64_t no_room = pages ? pages->figures().not_placed : 0;
    run_pass(Pass::records, cols, rows);
    // a paged model: again once the blocks its rays missed are up
    while (brought_wanted_blocks())
        run_pass(Pass::records, cols, rows);
    if (pages && pages->figures().not_placed != no_room)
        return false; // rays that met a block with no room show nothing
    // 2. the kernel's cells and camera (and the smoothing's weights)
    kernel_buffers_.set_kernel(tracer_, camera, shading, pixels);
    // 3. every pixel's view depth; with smoothing, every hit's kernel
    // normal and their sums along the rows
    view_.bind(0);
    kernel_buffers_.bind();
    run_pass(Pass::kernel_depth, cols, rows);
    if (kernel_buffers_.smoothing()) {
        // the normals pass reads the faces' normals as shading does
        shading_inputs_.bind(sbrt::make_gpu_shade(tracer_, shading, sbrt::Outputs{}), shading,
                             stats_);
        run_pass(Pass::kernel_normals, cols, rows);
        run_pass(Pass::kernel_across, cols, rows);
    }
    gl_.Finish();
    check_gl(gl_, "the kernel normals' trace, depth and smoothing passes");
    stats_.trace_ms += ms_since(start);
    return true;
}

void GpuTracer::shade_kernel_rows(const sbrt::Camera &camera, int first_row, int row_count,
                                  const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                                  sbrt::Band &band, unsigned cpu_threads)
{
    sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    const sbrt::GpuBandLayout layout = band_layout(camera, row_count, outputs, shade);
    GlComputeProgram &program = shading_program(shading, Pass::kernel_shade);
    const int cols = camera.cols();
    sbrt::GpuView view = sbrt::make_gpu_view(tracer_, camera, loop_budget_);
    view_.upload(&view, sizeof view);
    program.use();
    view_.bind(0);
    shading_inputs_.bind(shade, shading, stats_);
    kernel_buffers_.bind();
    shade_band(camera, first_row, row_count, shading, layout, band, cpu_threads,
               [&](int first, int count, int) {
                   kernel_buffers_.set_rows(first, count);
                   timer_.time(int(Pass::kernel_shade), [&] {
                       gl_.DispatchCompute(GLuint((cols + 7) / 8), GLuint((count + 7) / 8), 1);
                   });
               },
               false); // the kernel's shading reads the records, not the model
}

} // namespace sbrt_gl
