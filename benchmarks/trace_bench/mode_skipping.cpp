/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench skipping: the exact tracer with and without
 *            empty-space skipping, and with skipping but without the
 *            coarse first pass; on the GL path too where a context opens,
 *            in both GPU memory layouts with their bytes.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>

#include "gpu_tracer.hpp"
#include "modes.hpp"
#include "tracing/cpu_tracing.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// The GL path on the same view, in both memory layouts: `auto` picks the
/// faster of it and the CPU (`on_ms`, skipping and the first pass on).
void gl_skipping(sbrt_gl::GlContext &context, const Tracer &plain, const Tracer &skipping,
                 const Bench &bench, double on_ms)
{
    const std::string label = bench.args.get("label", "view");
    const Camera &camera = bench.camera;
    const double rays = double(camera.rows()) * camera.cols();
    for (GpuLayout layout : {GpuLayout::ssbo, GpuLayout::textures}) {
        sbrt_gl::GpuTracer gpu_plain(context, plain, layout);
        sbrt_gl::GpuTracer gpu(context, skipping, layout);
        const std::vector<double> gl_ms =
            best_ms_in_turns(bench.repeat, {[&] { gpu_plain.trace_image(camera); },
                                            [&] { gpu.trace_image(camera); }});
        const double gl_off = gl_ms[0], gl_on = gl_ms[1];
        const GpuMemory &m = gpu.memory();
        std::printf("skipping view=%s backend=%s layout=%s renderer=\"%s\" ms=%.1f "
                    "Mrays/s=%.2f skipping_off_ms=%.1f off/on=%.2f gl/cpu=%.2f "
                    "gpu_bytes=%llu index_bytes=%llu interval_bytes=%llu waste_bytes=%llu "
                    "pyramid_bytes=%zu\n",
                    label.c_str(), context.name().c_str(), gpu_layout_name(layout),
                    gpu.gl_renderer().c_str(), gl_on, rays / gl_on / 1e3, gl_off,
                    gl_off / gl_on, gl_on / on_ms, (unsigned long long)m.total(),
                    (unsigned long long)m.index_bytes, (unsigned long long)m.interval_bytes,
                    (unsigned long long)m.waste_bytes, gpu.pyramid_bytes());
    }
}

} // namespace

void run_skipping(const Bench &bench)
{
    const std::string label = bench.args.get("label", "view");
    const Camera &camera = bench.camera;
    const double rays = double(camera.rows()) * camera.cols();
    std::unique_ptr<sbrt_gl::GlContext> context = gl_context(bench.args);
    Scene no_skipping;
    no_skipping.skip_empty_space = false;
    const Tracer plain(bench.model, bench.zexag, no_skipping), skipping(bench.model, bench.zexag);
    // skipping off; on without the coarse first pass; on with it
    const std::vector<double> ms = best_ms_in_turns(
        bench.repeat, {[&] { trace_image(plain, camera); },
                       [&] { trace_image(skipping, camera, 0, false); },
                       [&] { trace_image(skipping, camera); }});
    const double off_ms = ms[0], on_ms = ms[2];
    for (int k : {2, 1, 0})
        std::printf("skipping view=%s backend=cpu skipping=%s first_pass=%s ms=%.1f "
                    "Mrays/s=%.2f\n",
                    label.c_str(), k ? "on" : "off", k == 2 ? "on" : "off", ms[k],
                    rays / ms[k] / 1e3);
    std::printf("skipping view=%s backend=cpu off/on=%.2f first_pass_off/on=%.2f\n",
                label.c_str(), off_ms / on_ms, ms[1] / on_ms);
    if (context)
        gl_skipping(*context, plain, skipping, bench, on_ms);
}

} // namespace trace_bench
