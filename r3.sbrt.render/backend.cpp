/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Backend choice and timing messages
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "backend.hpp"
#include "column_reading.hpp"

#include <algorithm>

#include <optional>

#include "util/error.hpp"
#include "gpu_renderer.hpp"
#include "util/parallel.hpp"
#include "request_error.hpp"

namespace {

void report(const char *what, const sbrt::Camera &camera, double ms)
{
    G_verbose_message(_("%s: %d x %d rays in %.1f ms (%.2f Mrays/s)"), what,
                      camera.cols(), camera.rows(), ms,
                      camera.rows() * double(camera.cols()) / ms / 1000);
}

void report_bands(const sbrt::RenderReport &r)
{
    G_verbose_message(_("Streamed: %d bands of %d rows, at most %d rows of hits "
                        "held; %.1f ms in all, of which the maps took %.1f ms "
                        "on their own thread"),
                      r.bands, r.band_rows, r.most_rows_held, r.ms, r.sink_ms);
}

void render_on_cpu(const RenderRequest &request, const sbrt::Renderer &renderer,
                   const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                   const sbrt::BandSink &sink)
{
    G_verbose_message(_("Backend: cpu (exact double-precision ray caster, %u "
                        "threads)"),
                      sbrt::thread_count(unsigned(request.threads)));
    const sbrt::RenderReport r = renderer.render(camera, outputs, sink);
    if (r.first_pass.tiles)
        G_verbose_message(_("First pass: %zu tiles of %d x %d pixels, %zu of them "
                            "meet nothing (%.1f ms)"),
                          r.first_pass.tiles, sbrt::FIRST_PASS_TILE,
                          sbrt::FIRST_PASS_TILE, r.first_pass.empty_tiles,
                          r.first_pass.ms);
    report_bands(r);
    report(_("CPU shading and tracing"), camera, r.trace_ms);
    sbrt_grass::report_paging(renderer.model());
}

/// A model read block by block on the GPU: its atlas, and this frame's
/// dispatches again for the blocks brought up.
void report_gpu_pages(const sbrt_gl::GpuModel &model, const sbrt_gl::GpuStats &frame)
{
    const sbrt_gl::GpuPageAtlas &pages = *model.pages();
    const sbrt_gl::PageFigures &f = pages.figures();
    if (model.plan().form.column_pages)
        G_verbose_message(_("GPU: the columns' top intervals and ranges in pages beside the "
                            "blocks', the empty-space pyramid from level %d on"),
                          model.plan().first_level);
    G_verbose_message(_("GPU blocks (gpu_memory=): %d up, %.1f of %.1f MB; %llu brought up "
                        "so far (%.1f MB), %llu dropped for others' room, %llu found no room, "
                        "%llu bands that let earlier bands' blocks go"),
                      pages.held_blocks(), double(pages.held_bytes()) / (1 << 20),
                      double(pages.atlas_bytes()) / (1 << 20), (unsigned long long)f.uploads,
                      double(f.upload_bytes) / (1 << 20), (unsigned long long)f.dropped,
                      (unsigned long long)f.not_placed, (unsigned long long)f.band_restarts);
    G_verbose_message(_("This frame: %d dispatches again for blocks brought up; %.1f ms "
                        "finding, decoding and bringing them up"),
                      frame.page_passes, frame.page_ms);
}

void render_on_gpu(const RenderRequest &request, const sbrt::Camera &camera,
                   const sbrt::Outputs &outputs, const sbrt::BandSink &sink,
                   sbrt_gl::GpuRenderer &gpu, bool first)
{
    const sbrt::GpuMemory &m = gpu.gpu().memory();
    G_verbose_message(_("GPU memory, layout=%s: %llu bytes (index %llu, intervals "
                        "%llu), of which %llu hold nothing"),
                      sbrt::gpu_layout_name(gpu.gpu().layout()),
                      (unsigned long long)m.total(), (unsigned long long)m.index_bytes,
                      (unsigned long long)m.interval_bytes,
                      (unsigned long long)m.waste_bytes);
    G_verbose_message(_("GL_VERSION: %s"), gpu.gpu().gl_version().c_str());
    G_verbose_message(_("GL_RENDERER: %s"), gpu.gpu().gl_renderer().c_str());
    const sbrt_gl::GpuFrameReport r =
        gpu.render(camera, outputs, sink, unsigned(request.threads));
    G_verbose_message(r.shaded_on_gpu ? _("Shading: on the GPU")
                      : gpu.shaded_on_host(outputs)
                          ? _("Shading: on the CPU at the GPU's hits (these colours "
                              "by voxel are made on the host)")
                          : _("Shading: on the CPU (kernel normals of an image "
                              "whose hits do not fit the GPU)"));
    if (first) {
        G_verbose_message(_("Model upload: %.1f ms (kept for the next frames)"),
                          r.gpu.upload_ms);
        G_verbose_message(_("GPU programs: %.1f ms (compiled, or loaded from the program "
                            "cache where an earlier run compiled them)"),
                          r.gpu.programs_ms);
    }
    if (r.shaded_on_gpu)
        G_verbose_message(_("Bands back: %d, in host memory as the GPU wrote them (%.2f bytes "
                            "a pixel); the host's time after the last: %.2f ms"),
                          r.gpu.bands,
                          double(r.gpu.host_bytes) /
                              std::max(1.0, double(camera.rows()) * double(camera.cols())),
                          r.host_after_ms);
    else
        G_verbose_message(_("Bands back: %d, hit records read back and decoded in %.1f ms"),
                          r.gpu.bands, r.gpu.readback_ms);
    report_bands(r.render);
    report(_("GPU tracing"), camera, r.gpu.trace_ms);
    if (r.gpu.over_budget)
        G_verbose_message(_("%zu rays exceeded the shader's loop budget%s and "
                            "were traced on the CPU"),
                          r.gpu.over_budget,
                          gpu.gpu().model().pages() ? _(" or met a block not on the GPU")
                                                    : "");
    if (gpu.gpu().model().pages())
        report_gpu_pages(gpu.gpu().model(), r.gpu);
    sbrt_grass::report_paging(gpu.renderer().model());
}

} // namespace

std::unique_ptr<sbrt_gl::GlContext> choose_gl_context(const RenderRequest &request)
{
    if (request.backend == "cpu")
        return nullptr;
    if (request.backend == "auto" && sbrt_gl::gpu_device_node().empty()) {
        // only a software GL could answer: not worth loading it
        G_verbose_message(_("No GPU device (/dev/dri/renderD*, /dev/nvidiactl, /dev/dxg): "
                            "using the CPU"));
        return nullptr;
    }
    std::unique_ptr<sbrt_gl::GlContext> context;
    try {
        context = sbrt_gl::create_gl_context(request.backend);
    }
    catch (const sbrt::Error &e) {
        if (request.backend != "auto")
            bad_request(_("backend=%s: %s"), request.backend.c_str(), e.what());
        G_verbose_message(_("No OpenGL context (%s): using the CPU"), e.what());
        return nullptr;
    }
    if (request.backend == "auto") {
        const sbrt_gl::GlApi gl(*context);
        const std::string renderer =
            reinterpret_cast<const char *>(gl.GetString(GL_RENDERER));
        if (sbrt_gl::is_software_renderer(renderer)) {
            G_verbose_message(_("OpenGL renderer <%s> of %s is software: the "
                                "CPU ray caster is faster on the same cores"),
                              renderer.c_str(), context->name().c_str());
            return nullptr;
        }
    }
    G_verbose_message(_("Backend: %s"), context->name().c_str());
    return context;
}

Backend::Backend(const RenderRequest &request, const sbrt::Renderer &renderer,
                 sbrt_gl::GlContext *context,
                 std::shared_ptr<sbrt_gl::GpuPageAtlas> *kept_atlas)
    : request_(request), renderer_(renderer), context_(context), kept_atlas_(kept_atlas)
{
}

void Backend::render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                     const sbrt::BandSink &sink)
{
    if (context_ && !tried_gpu_) {
        tried_gpu_ = true;
        try {
            sbrt_gl::GpuOptions options =
                sbrt_gl::GpuOptions::from_environment(sbrt::parse_gpu_layout(request_.gpu_layout));
            options.page_budget_bytes = request_.gpu_memory_bytes;
            options.kept_atlas = kept_atlas_;
            gpu_.emplace(*context_, renderer_, options);
        }
        catch (const sbrt::Error &e) {
            // the model does not fit this GPU's buffers
            if (request_.backend != "auto")
                throw;
            G_message(_("The GPU cannot take this model (%s): rendering on the CPU"),
                      e.what());
        }
    }
    if (gpu_)
        render_on_gpu(request_, camera, outputs, sink, *gpu_, frames_++ == 0);
    else
        render_on_cpu(request_, renderer_, camera, outputs, sink);
}
