/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Backend choice and timing messages
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "backend.hpp"

#include <chrono>
#include <memory>
#include <thread>

#include "cpu_tracing.hpp"
#include "error.hpp"
#include "gpu_tracer.hpp"

namespace {

using Clock = std::chrono::steady_clock;

bool is_software_renderer(const std::string &renderer)
{
    for (const char *name : {"llvmpipe", "softpipe", "swrast", "Software"})
        if (renderer.find(name) != std::string::npos)
            return true;
    return false;
}

void report(const char *what, int rows, int cols, double ms)
{
    G_verbose_message(_("%s: %d x %d rays in %.1f ms (%.2f Mrays/s)"), what,
                      cols, rows, ms, rows * double(cols) / ms / 1000);
}

sbrt::HitImage trace_on_cpu(const RenderRequest &request,
                            const sbrt::Tracer &tracer,
                            const sbrt::Camera &camera)
{
    G_verbose_message(_("Backend: cpu (exact double-precision ray caster, %d "
                        "threads)"),
                      request.threads ? request.threads
                                      : int(std::thread::hardware_concurrency()));
    const auto start = Clock::now();
    sbrt::FirstPassReport first_pass;
    sbrt::HitImage hits =
        sbrt::trace_image(tracer, camera, unsigned(request.threads), true, &first_pass);
    if (first_pass.tiles)
        G_verbose_message(_("First pass: %zu tiles of %d x %d pixels, %zu of them "
                            "meet nothing (%.1f ms)"),
                          first_pass.tiles, sbrt::FIRST_PASS_TILE, sbrt::FIRST_PASS_TILE,
                          first_pass.empty_tiles, first_pass.ms);
    report(_("CPU tracing"), camera.rows(), camera.cols(),
           std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    return hits;
}

sbrt::HitImage trace_on_gpu(const RenderRequest &request,
                            const sbrt::Tracer &tracer,
                            const sbrt::Camera &camera,
                            const sbrt_gl::GlContext &context)
{
    sbrt_gl::GpuTracer gpu(context, tracer, sbrt::parse_gpu_layout(request.gpu_layout));
    G_verbose_message(_("Backend: %s"), context.name().c_str());
    const sbrt::GpuMemory &m = gpu.memory();
    G_verbose_message(_("GPU memory, layout=%s: %llu bytes (index %llu, intervals "
                        "%llu), of which %llu hold nothing"),
                      sbrt::gpu_layout_name(gpu.layout()),
                      (unsigned long long)m.total(), (unsigned long long)m.index_bytes,
                      (unsigned long long)m.interval_bytes,
                      (unsigned long long)m.waste_bytes);
    G_verbose_message(_("GL_VERSION: %s"), gpu.gl_version().c_str());
    G_verbose_message(_("GL_RENDERER: %s"), gpu.gl_renderer().c_str());
    sbrt::HitImage hits =
        gpu.trace_image(camera, unsigned(request.threads));
    const sbrt_gl::GpuStats &s = gpu.stats();
    G_verbose_message(_("Model upload: %.1f ms; read back: %.1f ms; %d "
                        "band(s)"),
                      s.upload_ms, s.readback_ms, s.bands);
    report(_("GPU tracing"), camera.rows(), camera.cols(), s.trace_ms);
    if (s.over_budget)
        G_verbose_message(_("%zu rays exceeded the shader's loop budget and "
                            "were traced on the CPU"),
                          s.over_budget);
    return hits;
}

} // namespace

sbrt::HitImage trace_hits(const RenderRequest &request,
                          const sbrt::Tracer &tracer,
                          const sbrt::Camera &camera)
{
    if (request.backend == "cpu")
        return trace_on_cpu(request, tracer, camera);
    if (tracer.has_overlays()) {
        if (request.backend != "auto")
            G_warning(_("backend=%s: boreholes and fence curtains are drawn by "
                        "the CPU ray caster only; using it"),
                      request.backend.c_str());
        return trace_on_cpu(request, tracer, camera);
    }
    std::unique_ptr<sbrt_gl::GlContext> context;
    try {
        context = sbrt_gl::create_gl_context(request.backend);
    }
    catch (const sbrt::Error &e) {
        if (request.backend != "auto")
            G_fatal_error(_("backend=%s: %s"), request.backend.c_str(), e.what());
        G_verbose_message(_("No OpenGL context (%s): using the CPU"), e.what());
        return trace_on_cpu(request, tracer, camera);
    }
    if (request.backend == "auto") {
        const sbrt_gl::GlApi gl(*context);
        const std::string renderer =
            reinterpret_cast<const char *>(gl.GetString(GL_RENDERER));
        if (is_software_renderer(renderer)) {
            G_verbose_message(_("OpenGL renderer <%s> of %s is software: the "
                                "CPU ray caster is faster on the same cores"),
                              renderer.c_str(), context->name().c_str());
            context.reset();
            return trace_on_cpu(request, tracer, camera);
        }
    }
    return trace_on_gpu(request, tracer, camera, *context);
}
