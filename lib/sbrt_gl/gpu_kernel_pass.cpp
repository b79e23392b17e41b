/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Image-space kernel normals on the GPU (shaders/kernel_*.comp):
 *            the whole image's hit records and view depths kept on the
 *            GPU, then the kernel normals and shading of each band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_kernel_pass.hpp"

#include "gpu_internal.hpp"

namespace sbrt_gl {

bool GpuKernelPass::fits(const sbrt::Camera &camera) const
{
    // the GPU writes no hit records of boreholes and curtains alone
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    return passes_.tracer.scene().draw_model && !camera.is_window() &&
           pixels * sizeof(sbrt::GpuPixelHit) <= passes_.max_block_bytes;
}

bool GpuKernelPass::prepare(const sbrt::Camera &camera, const sbrt::Shading &shading,
                            sbrt::GpuView view)
{
    const sbrt::Tracer &tracer = passes_.tracer;
    const int rows = camera.rows(), cols = camera.cols();
    const size_t pixels = size_t(rows) * size_t(cols);
    // 1. the hit records of the whole image, kept on the GPU
    passes_.upload_view(view, 0, rows);
    buffers_.bind_image_records(pixels);
    const auto start = Clock::now();
    const GpuPageAtlas *pages = passes_.model.pages();
    // a crowded atlas: the whole image's pages would not fit (the host
    // finds the normals from the hits)
    if (pages && pages->crowded())
        return false;
    const uint64_t no_room = pages ? pages->figures().not_placed : 0;
    passes_.run_pass(Pass::records, cols, rows);
    // a paged model: again once the blocks its rays missed are up
    while (passes_.brought_wanted_blocks())
        passes_.run_pass(Pass::records, cols, rows);
    if (pages && pages->figures().not_placed != no_room)
        return false; // rays that met a block with no room show nothing
    // 2. the kernel's cells and camera (and the smoothing's weights)
    buffers_.set_kernel(tracer, camera, shading, pixels);
    // 3. every pixel's view depth; with smoothing, every hit's kernel
    // normal and their sums along the rows
    passes_.view.bind(0);
    buffers_.bind();
    passes_.run_pass(Pass::kernel_depth, cols, rows);
    if (buffers_.smoothing()) {
        // the normals pass reads the faces' normals as shading does
        shading_inputs_.bind(sbrt::make_gpu_shade(tracer, shading, sbrt::Outputs{}), shading,
                             passes_.stats);
        passes_.run_pass(Pass::kernel_normals, cols, rows);
        passes_.run_pass(Pass::kernel_across, cols, rows);
    }
    passes_.gl.Finish();
    check_gl(passes_.gl, "the kernel normals' trace, depth and smoothing passes");
    passes_.stats.trace_ms += ms_since(start);
    return true;
}

void GpuKernelPass::begin_shading(const sbrt::Camera &camera, const sbrt::Shading &shading,
                                  const sbrt::GpuShade &shade, uint32_t loop_budget)
{
    GlComputeProgram &program = passes_.shading_program(shading, Pass::kernel_shade);
    sbrt::GpuView view = sbrt::make_gpu_view(passes_.tracer, camera, loop_budget);
    passes_.view.upload(&view, sizeof view);
    program.use();
    passes_.view.bind(0);
    shading_inputs_.bind(shade, shading, passes_.stats);
    buffers_.bind();
}

void GpuKernelPass::dispatch_shading(const sbrt::Camera &camera, int first, int count)
{
    buffers_.set_rows(first, count);
    passes_.dispatch(Pass::kernel_shade, camera.cols(), count);
}

} // namespace sbrt_gl
