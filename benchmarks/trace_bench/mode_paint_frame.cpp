/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench paint_frame: the class view against a property
 *            (property=a+b: the channels' sum through a ramp over their
 *            stated range) and a fade (fade=c, 0..100) on the GPU (gpu=)
 *            and the CPU (threads=): each kind's first frame of a fresh
 *            GPU renderer with fresh channels (nothing decoded, the
 *            colours by voxel made and uploaded; the GL programs come from
 *            the cache, filled by a frame before; and coloured on the host
 *            at the GPU's hits instead), its warm frame (best of `repeat`
 *            back to back, after 0.3 s of them), the CPU's warm frame,
 *            whether the GPU shaded it, and the pixels whose colour
 *            differs from the CPU's by more than one level.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>

#include "format/format.hpp"
#include "gpu_renderer.hpp"
#include "gpu_tracer.hpp"
#include "modes.hpp"
#include "renderer.hpp"
#include "shading/property_paint.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// A kind of view: class, property (what: a+b) or fade (what: c).
struct Kind {
    std::string name, what;
};

/// The shading of a kind over fresh channels (nothing decoded).
struct Painted {
    std::shared_ptr<const PropertyChannels> channels;
    std::unique_ptr<PropertyPaint> property;
    std::unique_ptr<UncertaintyFade> fade;
    Shading shading;
};

size_t channel_of(const PropertyChannels &channels, const std::string &name,
                  const std::string &dir)
{
    const int k = channels.find(name);
    if (k < 0)
        fail("no channel ", name, " in ", dir);
    return size_t(k);
}

/// The sum of kind.what's channels through viridis over their stated range.
void paint_property(Painted &p, const Kind &kind, const Model &as_read, const std::string &dir)
{
    std::vector<size_t> summed;
    double low = 0, high = 0;
    std::stringstream in(kind.what);
    for (std::string name; std::getline(in, name, '+');) {
        summed.push_back(channel_of(*p.channels, name, dir));
        const ChannelInfo &info = p.channels->info(summed.back());
        low += std::min(info.physical(float(info.min)), info.physical(float(info.max)));
        high += std::max(info.physical(float(info.min)), info.physical(float(info.max)));
    }
    if (!(high > low))
        high = low + 1;
    const ColorRamp viridis = ColorRamp::through(
        {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}, low, high);
    p.property = std::make_unique<PropertyPaint>(as_read, p.channels, summed, viridis);
    p.shading.property = p.property.get();
}

Painted painted(const Kind &kind, const Model &as_read, const std::string &dir)
{
    Painted p;
    if (kind.name == "class")
        return p;
    p.channels = read_channels(dir, as_read);
    if (!p.channels)
        fail(dir, " has no property channels");
    if (kind.name == "fade") {
        p.fade = std::make_unique<UncertaintyFade>(
            as_read, p.channels, channel_of(*p.channels, kind.what, dir), 0, 100);
        p.shading.fade = p.fade.get();
        return p;
    }
    paint_property(p, kind, as_read, dir);
    return p;
}

/// Where the warm frame's time goes: each pass's GL time, the rays the
/// host traced and coloured (flagged by the shader), its time.
void print_paint_parts(sbrt_gl::GpuRenderer &on_gpu, const Camera &camera, unsigned threads,
                       const std::string &label, const Kind &kind)
{
    on_gpu.gpu().time_passes(true);
    const sbrt_gl::GpuFrameReport parts = on_gpu.render(camera, {}, [](const Band &) {}, threads);
    on_gpu.gpu().time_passes(false);
    std::string passes;
    for (size_t k = 0; k < parts.gpu.pass_ms.size(); ++k)
        if (parts.gpu.pass_ms[k] > 0)
            passes += std::string(" gl_") + sbrt_gl::pass_name(int(k)) + "_ms=" +
                      std::to_string(parts.gpu.pass_ms[k]);
    std::printf("paint_parts label=%s kind=%s%s over_budget=%zu host_traced_ms=%.3f "
                "before_dispatch_ms=%.3f gpu_wait_ms=%.3f host_after_ms=%.3f frame_ms=%.3f\n",
                label.c_str(), kind.name.c_str(), passes.c_str(), parts.gpu.over_budget,
                parts.gpu.readback_ms, parts.gpu.before_dispatch_ms, parts.gpu.trace_ms,
                parts.host_after_ms, parts.render.ms);
}

/// The first and warm frames of one kind, printed; returns {first, warm}.
std::pair<double, double> paint_kind(const Bench &bench, sbrt_gl::GlContext &context,
                                     Renderer &renderer, const Model &as_read, const Kind &kind)
{
    const Camera &camera = bench.camera;
    const std::string label = bench.args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(bench.args.get("threads", "0")));
    const BandSink none = [](const Band &) {};
    // the GL programs into the cache (not timed)
    {
        Painted p = painted(kind, as_read, bench.dir);
        renderer.set_shading(p.shading);
        sbrt_gl::GpuRenderer on_gpu(context, renderer);
        on_gpu.render(camera, {}, none, threads);
    }
    // cold: fresh channels, a fresh GPU renderer, its first frame
    Painted p = painted(kind, as_read, bench.dir);
    renderer.set_shading(p.shading);
    bool on_gpu_shaded = false;
    std::unique_ptr<sbrt_gl::GpuRenderer> on_gpu;
    const double first = run_ms([&] {
        on_gpu = std::make_unique<sbrt_gl::GpuRenderer>(context, renderer);
        on_gpu_shaded = on_gpu->render(camera, {}, none, threads).shaded_on_gpu;
    });
    const double upload_ms = on_gpu->gpu().stats().upload_ms;
    const double paint_ms = on_gpu->gpu().stats().paint_ms;
    // cold again, the host colouring at the GPU's hits (decoding only the
    // blocks rays reach)
    double first_host = NAN;
    if (kind.name != "class") {
        Painted fresh = painted(kind, as_read, bench.dir);
        renderer.set_shading(fresh.shading);
        first_host = run_ms([&] {
            sbrt_gl::GpuRenderer host_coloured(context, renderer);
            host_coloured.paint_on_gpu(false);
            host_coloured.render(camera, {}, none, threads);
        });
        renderer.set_shading(p.shading);
    }
    // warm: back to back after 0.3 s of frames
    warm_up_gpu(*on_gpu, camera, none, threads);
    const double warm =
        best_ms(bench.repeat, [&] { on_gpu->render(camera, {}, none, threads); });
    print_paint_parts(*on_gpu, camera, threads, label, kind);
    const size_t apart = pixels_apart(on_gpu->render_image(camera, {}, threads).rgb,
                                      renderer.render_image(camera, {}).rgb);
    const double cpu = best_ms(bench.repeat, [&] { renderer.render(camera, {}, none); });
    const double rays = double(camera.rows()) * camera.cols();
    std::printf("paint_frame label=%s kind=%s%s%s renderer=\"%s\" cols=%d rows=%d "
                "shaded_on_gpu=%s first_frame_ms=%.2f upload_ms=%.2f paint_ms=%.2f "
                "first_frame_host_coloured_ms=%.2f frame_ms=%.3f "
                "mrays=%.0f cpu_frame_ms=%.1f cpu_threads=%u gpu/cpu=%.1f "
                "pixels_apart_from_cpu=%zu of %.0f\n",
                label.c_str(), kind.name.c_str(), kind.what.empty() ? "" : "=", kind.what.c_str(),
                on_gpu->gpu().gl_renderer().c_str(), camera.cols(), camera.rows(),
                on_gpu_shaded ? "yes" : "no", first, upload_ms, paint_ms, first_host, warm,
                rays / warm / 1000, cpu, thread_count(threads), cpu / warm, apart, rays);
    return {first, warm};
}

} // namespace

void run_paint_frame(const Bench &bench)
{
    const std::string &dir = bench.dir;
    const Args &args = bench.args;
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    const Model as_read = read_sbrt(dir);
    const std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    if (!context) {
        std::printf("paint_frame label=%s no_gl_context\n", label.c_str());
        return;
    }
    // the kinds: class, property, fade (those asked for)
    std::vector<Kind> kinds{{"class", ""}};
    if (!args.get("property", "").empty())
        kinds.push_back({"property", args.get("property", "")});
    if (!args.get("fade", "").empty())
        kinds.push_back({"fade", args.get("fade", "")});
    Renderer renderer(read_sbrt(dir), bench.zexag, Scene{}, Shading{},
                      RenderSettings{threads, true, 0});
    std::map<std::string, double> warm_ms, first_ms;
    for (const Kind &kind : kinds)
        std::tie(first_ms[kind.name], warm_ms[kind.name]) =
            paint_kind(bench, *context, renderer, as_read, kind);
    for (const Kind &kind : kinds)
        if (kind.name != "class")
            std::printf("paint_frame label=%s %s/class first_frame=%.2f warm_frame=%.2f\n",
                        label.c_str(), kind.name.c_str(), first_ms[kind.name] / first_ms["class"],
                        warm_ms[kind.name] / warm_ms["class"]);
}

} // namespace trace_bench
