/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench gpu_pages: a model read block by block (its
 *            blocks decoded within memory=, MB, default 300) drawn on the
 *            GPU (gpu=, default egl) with its blocks brought up as rays
 *            reach them, for each gpu_memory= (MB, a list; default 1024):
 *            the cold frame (a new GPU renderer: the pyramid and the tops
 *            up, every block brought up) and the best warm frame, what the
 *            atlas did, the rays traced on the CPU, the pixels apart from
 *            the CPU's frame (timed before, cold and warm: cpu=0, none);
 *            with whole=1 the same frames of the model decoded and
 *            uploaded whole; with columns=L the columns' tops and ranges
 *            in pages, the pyramid from level L on (as a model many times
 *            national goes up). Each renderer opens the model afresh (no
 *            block decoded before its first frame).
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "format/format.hpp"
#include "gpu_page_atlas.hpp"
#include "gpu_renderer.hpp"
#include "modes.hpp"
#include "renderer.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// The model of `dir` paged within `memory_mb`.
Model paged_model(const std::string &dir, double memory_mb, unsigned threads)
{
    Paging paging;
    paging.budget_bytes = uint64_t(memory_mb * (1 << 20));
    paging.threads = threads;
    std::optional<Model> model = read_sbrt_paged(dir, paging);
    if (!model)
        fail("gpu_pages: ", dir, " cannot be read block by block (format 2.0 or older, or "
                                 "property channels)");
    return std::move(*model);
}

/// Cold and warm frames of `renderer` on the GPU with `options`, printed.
void print_gpu_frames(const sbrt_gl::GlContext &context, const Renderer &renderer,
                      const sbrt_gl::GpuOptions &options, const Camera &camera,
                      const Bench &bench, const std::string &what, const Image &cpu)
{
    const unsigned threads = unsigned(std::stoi(bench.args.get("threads", "0")));
    size_t checksum = 0;
    const BandSink sink = checksum_sink(checksum);
    std::optional<sbrt_gl::GpuRenderer> on_gpu;
    sbrt_gl::GpuFrameReport cold;
    const double cold_ms = run_ms([&] {
        on_gpu.emplace(context, renderer, options);
        cold = on_gpu->render(camera, {}, sink, threads);
    });
    sbrt_gl::GpuFrameReport warm;
    const double warm_ms = best_ms(bench.repeat, [&] {
        warm = on_gpu->render(camera, {}, sink, threads);
    });
    const sbrt_gl::GpuPageAtlas *pages = on_gpu->gpu().model().pages();
    const sbrt_gl::PageFigures f = pages ? pages->figures() : sbrt_gl::PageFigures{};
    const size_t apart =
        cpu.rgb.empty() ? 0 : pixels_apart(on_gpu->render_image(camera, {}, threads).rgb, cpu.rgb);
    std::printf("gpu_pages label=%s model=%s renderer=\"%s\" cols=%d rows=%d gpu_memory_mb=%.0f "
                "cold_ms=%.1f upload_ms=%.1f warm_ms=%.2f gpu_total_mb=%.1f blocks_up=%d "
                "atlas_mb=%.1f held_mb=%.1f uploads=%llu not_placed=%llu cold_passes=%d "
                "page_ms=%.1f cold_cpu_rays=%zu warm_cpu_rays=%zu pixels_apart_from_cpu=%zu "
                "column_pages=%d first_level=%d band_restarts=%llu (checksum %zu)\n",
                bench.args.get("label", "view").c_str(), what.c_str(),
                on_gpu->gpu().gl_renderer().c_str(), camera.cols(), camera.rows(),
                double(options.page_budget_bytes) / (1 << 20), cold_ms, cold.gpu.upload_ms,
                warm_ms,
                double(on_gpu->gpu().memory().total() + on_gpu->gpu().pyramid_bytes()) / (1 << 20),
                pages ? pages->held_blocks() : 0, pages ? double(pages->atlas_bytes()) / (1 << 20) : 0,
                pages ? double(pages->held_bytes()) / (1 << 20) : 0,
                (unsigned long long)f.uploads, (unsigned long long)f.not_placed,
                cold.gpu.page_passes, cold.gpu.page_ms, cold.gpu.over_budget,
                warm.gpu.over_budget, apart, int(on_gpu->gpu().model().plan().form.column_pages),
                on_gpu->gpu().model().plan().first_level, (unsigned long long)f.band_restarts,
                checksum);
}

} // namespace

void run_gpu_pages(const Bench &bench)
{
    const Args &args = bench.args;
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    const double memory_mb = std::stod(args.get("memory", "300"));
    // each renderer on a model opened afresh: no block decoded before
    const auto fresh_renderer = [&](double *open_ms) {
        Model paged;
        const double ms =
            run_ms([&] { paged = paged_model(bench.dir, memory_mb, threads); });
        if (open_ms)
            *open_ms = ms;
        return std::make_unique<Renderer>(std::move(paged), bench.zexag, Scene{}, Shading{},
                                          RenderSettings{threads, true, 0});
    };
    double open_ms = 0;
    const std::unique_ptr<Renderer> cpu_renderer = fresh_renderer(&open_ms);
    const Camera camera = camera_of(args, cpu_renderer->model(), bench.zexag);
    Image cpu;
    double cpu_cold_ms = NAN, cpu_ms = NAN;
    if (args.get("cpu", "1") != "0") {
        cpu_cold_ms = run_ms([&] { cpu = cpu_renderer->render_image(camera, {}); });
        cpu_ms = best_ms(bench.repeat, [&] { cpu = cpu_renderer->render_image(camera, {}); });
    }
    std::printf("gpu_pages label=%s open_ms=%.1f cpu_cold_frame_ms=%.1f cpu_frame_ms=%.1f\n",
                label.c_str(), open_ms, cpu_cold_ms, cpu_ms);
    const std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    if (!context) {
        std::printf("gpu_pages no_gl_context\n");
        return;
    }
    std::vector<double> budgets = args.numbers("gpu_memory");
    if (budgets.empty())
        budgets = {1024};
    for (double mb : budgets) {
        sbrt_gl::GpuOptions options = sbrt_gl::GpuOptions::from_environment();
        options.page_budget_bytes = uint64_t(mb * (1 << 20));
        options.column_pages_from_level = std::stoi(args.get("columns", "0"));
        try {
            const std::unique_ptr<Renderer> renderer = fresh_renderer(nullptr);
            print_gpu_frames(*context, *renderer, options, camera, bench, "paged", cpu);
        }
        catch (const Error &e) {
            std::printf("gpu_pages label=%s gpu_memory_mb=%.0f refused: %s\n", label.c_str(),
                        mb, e.what());
        }
    }
    if (args.get("whole", "0") != "1")
        return;
    try {
        Model whole;
        const double read_ms = run_ms([&] { whole = read_sbrt(bench.dir); });
        std::printf("gpu_pages label=%s whole_read_ms=%.1f\n", label.c_str(), read_ms);
        const Renderer whole_renderer(std::move(whole), bench.zexag, Scene{}, Shading{},
                                      RenderSettings{threads, true, 0});
        print_gpu_frames(*context, whole_renderer, sbrt_gl::GpuOptions::from_environment(),
                         camera, bench, "whole", cpu);
    }
    catch (const Error &e) {
        std::printf("gpu_pages label=%s whole refused: %s\n", label.c_str(), e.what());
    }
}

} // namespace trace_bench
