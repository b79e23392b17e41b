/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench frame: the streamed pipeline in process: load,
 *            prepare (Renderer), a whole frame (trace, shade, the RGB
 *            bands handed to a sink), warm, best of `repeat`, on threads=
 *            (0: all cores); beside it the whole-image reference
 *            (trace_image, then shade; reference=0: none), taken in turns;
 *            then where the best frame's time went (frame_parts).
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "modes.hpp"
#include "renderer.hpp"
#include "shading/shading.hpp"
#include "tracing/cpu_tracing.hpp"
#include "util/parallel.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// Where the best CPU frame's time went: each worker's share of the frame
/// spent finding first-pass bounds, tracing and shading (the rest it waited
/// or took work), the sum of the workers' busy time (against one thread's:
/// more work for the same rows as threads are added), the first pass's
/// wall time, and the sink thread's share.
void print_frame_parts(const RenderReport &r, const std::string &label)
{
    double busy_sum = 0, busy_min = INFINITY;
    for (double b : r.worker_busy_ms) {
        busy_sum += b;
        busy_min = std::min(busy_min, b);
    }
    const double workers = double(std::max<size_t>(r.worker_busy_ms.size(), 1));
    std::string shares;
    for (double b : r.worker_busy_ms)
        shares += (shares.empty() ? "" : ",") + std::to_string(int(std::lround(100 * b / r.ms)));
    std::printf("frame_parts label=%s threads=%zu frame_ms=%.2f first_pass_ms=%.2f rows_ms=%.2f "
                "busy_sum_ms=%.1f busy_mean_pct=%.1f busy_min_pct=%.1f band_wait_ms=%.2f "
                "sink_ms=%.2f sink_pct=%.1f bands=%d busy_pct_each=%s\n",
                label.c_str(), r.worker_busy_ms.size(), r.ms, r.first_pass.ms, r.trace_ms, busy_sum,
                100 * busy_sum / workers / r.ms, 100 * busy_min / r.ms, r.band_wait_ms, r.sink_ms,
                100 * r.sink_ms / r.ms, r.bands, shares.c_str());
}

} // namespace

void run_frame(const Bench &bench)
{
    const Args &args = bench.args;
    const Camera &camera = bench.camera;
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    Model model;
    const double load_ms = run_ms([&] { model = load(bench.dir, args); });
    std::unique_ptr<Renderer> renderer;
    const double prepare_ms = run_ms([&] {
        renderer = std::make_unique<Renderer>(std::move(model), bench.zexag, Scene{}, Shading{},
                                              RenderSettings{threads, true, 0});
    });
    size_t checksum = 0;
    const BandSink sink = checksum_sink(checksum);
    const Tracer &tracer = renderer->tracer();
    RenderReport best;
    best.ms = INFINITY;
    // the first frame on its own: a paged model's blocks are decoded in it
    size_t first_sum = 0; // (the checksum sums the timed frames alone, as before)
    const BandSink first_sink = checksum_sink(first_sum);
    const double first_frame_ms = run_ms([&] { renderer->render(camera, {}, first_sink); });
    std::vector<std::function<void()>> runs{[&] {
        RenderReport r = renderer->render(camera, {}, sink);
        if (r.ms < best.ms)
            best = std::move(r);
    }};
    // reference=0: the streamed frame alone (for a profiler)
    if (args.get("reference", "1") != "0")
        runs.push_back([&] {
            const Image image = shade(tracer, camera, trace_image(tracer, camera, threads),
                                      renderer->shading(), threads);
            checksum += image.rgb[image.rgb.size() / 2];
        });
    std::vector<double> ms = best_ms_in_turns(bench.repeat, runs);
    ms.resize(2, NAN);
    const double rays = double(camera.rows()) * camera.cols();
    std::printf("frame label=%s threads=%u cols=%d rows=%d load_ms=%.1f prepare_ms=%.1f "
                "frame_ms=%.1f mrays=%.2f reference_ms=%.1f first_frame_ms=%.1f (checksum %zu)\n",
                label.c_str(), thread_count(threads), camera.cols(), camera.rows(),
                load_ms, prepare_ms, ms[0], rays / ms[0] / 1000, ms[1], first_frame_ms, checksum);
    print_frame_parts(best, label);
}

} // namespace trace_bench
