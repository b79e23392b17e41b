/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   GPU tracing of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_tracer.hpp"

#include <algorithm>
#include <chrono>

#include "util/error.hpp"
#include "util/parallel.hpp"
#include "gpu_internal.hpp"
#include "gpu/gpu_overlays.hpp"
#include "gpu/gpu_paint.hpp"

namespace sbrt_gl {

namespace {

/// GL 4.4 core at least (compute shaders, SSBOs, persistently mapped
/// buffers); the largest SSBO binding.
size_t check_version(const GlApi &gl, const std::string &context)
{
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 44)
        sbrt::fail(context, ": OpenGL ", major, ".", minor,
                   " is below 4.4 (compute shaders, storage buffers, mapped buffers)");
    GLint64 block = 0;
    gl.GetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    return size_t(std::max<GLint64>(block, 0));
}

} // namespace

GpuTracer::GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
                     sbrt::GpuLayout layout, ProgramCache cache)
    : GpuTracer(context, tracer, GpuOptions::from_environment(layout), std::move(cache))
{
}

GpuTracer::GpuTracer(const GlContext &context, const sbrt::Tracer &tracer,
                     const GpuOptions &options, ProgramCache cache)
    : created_(Clock::now()), tracer_(tracer), gl_(context),
      max_block_bytes_(check_version(gl_, context.name())),
      model_(gl_, tracer, options, max_block_bytes_),
      programs_(gl_, tracer, model_, std::move(cache)),
      shading_inputs_(gl_, tracer, model_, max_block_bytes_),
      view_(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuView)), timer_(gl_),
      loop_budget_(sbrt_gl::loop_budget(options, gl_renderer())),
      passes_{gl_,    tracer_, model_,           programs_,
              view_,  timer_,  stats_,           max_block_bytes_,
              std::max(options.crowded_band_pixels, 1)},
      first_pass_(passes_), records_(passes_),
      shade_(passes_, sbrt_gl::staged_bands(options, gl_renderer())),
      boreholes_(passes_), kernel_(passes_, shading_inputs_)
{
    stats_.upload_ms = ms_since(created_);
}

std::string GpuTracer::gl_version() const
{
    return reinterpret_cast<const char *>(gl_.GetString(GL_VERSION));
}

std::string GpuTracer::gl_renderer() const
{
    return reinterpret_cast<const char *>(gl_.GetString(GL_RENDERER));
}

void GpuTracer::reset_stats()
{
    // what the tracer's life has cost so far, not a frame's
    const double upload_ms = stats_.upload_ms, paint_ms = stats_.paint_ms;
    stats_ = GpuStats();
    stats_.upload_ms = upload_ms;
    stats_.paint_ms = paint_ms;
    timer_.take_ms(0); // the queries of what went before
}

void GpuTracer::begin_frame()
{
    reset_stats();
    frame_start_ = Clock::now();
    shade_.begin_frame();
    if (GpuPageAtlas *pages = model_.pages())
        pages->begin_frame();
}

std::vector<double> GpuTracer::take_pass_ms()
{
    if (!timer_.enabled())
        return {};
    return timer_.take_ms(int(Pass::cull_tiles) + 1);
}

const char *pass_name(int k)
{
    static const char *const names[] = {"records",        "shade",         "kernel_depth",
                                        "kernel_normals", "kernel_across", "kernel_shade",
                                        "first_pass",     "shade_boreholes", "cull_tiles"};
    return k >= 0 && k < int(std::size(names)) ? names[k] : "?";
}

sbrt::HitImage GpuTracer::trace_image(const sbrt::Camera &camera,
                                      unsigned cpu_threads,
                                      uint32_t loop_budget)
{
    begin_frame();
    sbrt::HitImage hits(size_t(camera.rows()) * camera.cols());
    trace_rows(camera, 0, camera.rows(), hits.data(), cpu_threads, loop_budget);
    return hits;
}


const GlComputeProgram *GpuTracer::shading_program_built() const
{
    for (const ProgramVariant variant : {ProgramVariant{false, true}, ProgramVariant{true, false},
                                         ProgramVariant{}})
        if (const GlComputeProgram *program = programs_.built(Pass::shade, variant))
            return program;
    return nullptr;
}

void GpuTracer::bind_model() const
{
    model_.bind();
    view_.bind(0);
    first_pass_.bind();
}

void GpuTracer::trace_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           sbrt::Hit *out, unsigned cpu_threads, uint32_t loop_budget)
{
    if (!tracer_.scene().draw_model) {
        // boreholes and curtains alone: the GPU shades them (shade_rows),
        // a hit record would lack their surfaces' normals
        const int cols = camera.cols();
        sbrt::for_each_row(first_row, first_row + row_count, cpu_threads, [&](int row) {
            for (int col = 0; col < cols; ++col)
                tracer_.trace_into(camera.ray(row, col), 0,
                                   out[size_t(row - first_row) * cols + size_t(col)]);
        });
        return;
    }
    sbrt::GpuView view = first_pass_.view(camera, loop_budget);
    bind_model();
    records_.trace(camera, view, first_row, row_count, out, cpu_threads);
}

bool GpuTracer::paints(const sbrt::Shading &shading, const sbrt::Outputs &outputs) const
{
    return sbrt::gpu_paints(tracer_, shading, outputs) &&
           sbrt::gpu_paint_bytes(tracer_, shading) <= max_block_bytes_;
}

int GpuTracer::max_band_rows(int cols, const sbrt::Outputs &outputs) const
{
    const size_t row_bytes = sbrt::gpu_band_layout(1, cols, outputs).bytes();
    return int(std::clamp<size_t>(max_block_bytes_ / std::max<size_t>(row_bytes, 1), 1,
                                  size_t(INT32_MAX)));
}

void GpuTracer::shade_rows(const sbrt::Camera &camera, int first_row, int row_count,
                           const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                           sbrt::Band &band, unsigned cpu_threads)
{
    if ((shading.property || shading.fade) && !paints(shading, outputs))
        sbrt::fail("these colours by voxel are made on the host, not on the GPU");
    sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    const sbrt::GpuBandLayout layout = shade_.band_layout(camera, row_count, outputs, shade);
    // the model alone everywhere; with boreholes drawn with the model, the
    // model and the boreholes again over the tiles where a ray may meet one
    GpuShadePass::Plan plan = shade_.plan(camera, shading);
    plan.view = first_pass_.view(camera, loop_budget_);
    bind_model();
    shading_inputs_.bind(shade, shading, stats_);
    if (shading.property || shading.fade)
        shading_inputs_.bind_double_rays(camera);
    // a scratch buffer for each slot, as a band dispatched ahead writes its
    // own while the band before still reads
    shade_.set_scratch(plan.borehole_program ? boreholes_.scratch_bytes(camera, layout) : 0);
    shade_.shade(camera, first_row, row_count, shading, layout, band, cpu_threads,
                 [&](int first, int count, int slot) {
                     if (stats_.before_dispatch_ms == 0) // the first band
                         stats_.before_dispatch_ms = ms_since(frame_start_);
                     shade_.dispatch_model(camera, plan, first, count);
                     if (plan.borehole_program)
                         boreholes_.dispatch(camera, *plan.borehole_program,
                                             plan.every_tile, first, count, slot);
                 });
    if (plan.borehole_program) // the tiles listed in the band just done
        stats_.borehole_tiles += boreholes_.listed(shade_.last_slot());
}

bool GpuTracer::prepare_kernel(const sbrt::Camera &camera, const sbrt::Shading &shading)
{
    if (!kernel_.fits(camera))
        sbrt::fail("kernel normals on the GPU: the image's hit records do not fit one "
                   "storage buffer, or the GPU does not write them (boreholes and curtains "
                   "alone, a window of an image)");
    const sbrt::GpuView view = first_pass_.view(camera, loop_budget_);
    bind_model();
    return kernel_.prepare(camera, shading, view);
}

void GpuTracer::shade_kernel_rows(const sbrt::Camera &camera, int first_row, int row_count,
                                  const sbrt::Shading &shading, const sbrt::Outputs &outputs,
                                  sbrt::Band &band, unsigned cpu_threads)
{
    sbrt::GpuShade shade = sbrt::make_gpu_shade(tracer_, shading, outputs);
    const sbrt::GpuBandLayout layout = shade_.band_layout(camera, row_count, outputs, shade);
    kernel_.begin_shading(camera, shading, shade, loop_budget_);
    shade_.shade(camera, first_row, row_count, shading, layout, band, cpu_threads,
                 [&](int first, int count, int) { kernel_.dispatch_shading(camera, first, count); },
                 false); // the kernel's shading reads the records, not the model
}

} // namespace sbrt_gl
