/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench gpu_frame: the streamed frame on the GPU (gpu=,
 *            default egl): the model uploaded once, every frame traced,
 *            shaded (face, then kernel normals, not with boreholes=) and
 *            its RGB bands read back into host memory, warm, each kind
 *            back to back (warm_up_gpu); beside them the CPU's frame
 *            (threads=; cpu=0: none), where a GPU frame's time goes
 *            (gpu_parts), and the pixels of the GPU's image apart from the
 *            CPU's.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstdio>
#include <cstring>

#include "gpu_renderer.hpp"
#include "gpu_tracer.hpp"
#include "modes.hpp"
#include "renderer.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// boreholes=N on a grid over the model (each showing the model's stack
/// at its axis), radius= map units (default two cells).
Scene boreholes(const Model &model, const Args &args)
{
    Scene scene;
    const int n = std::stoi(args.get("boreholes", "0"));
    const Frame &f = model.frame();
    const int side = int(std::ceil(std::sqrt(double(std::max(n, 1)))));
    for (int k = 0; k < n; ++k) {
        const int row = int((k / side + 0.5) * f.rows / side);
        const int col = int((k % side + 0.5) * f.cols / side);
        Borehole b;
        b.x = f.west + (col + 0.5) * f.ew_res();
        b.y = f.north - (row + 0.5) * f.ns_res();
        b.stack = b.model_stack = model.stack_intervals(model.cell_index(row, col));
        if (!b.stack.empty())
            scene.boreholes.push_back(std::move(b));
    }
    scene.borehole_radius = std::stod(args.get("radius", std::to_string(2 * f.ew_res())));
    return scene;
}

/// The best time (ms) of one memcpy of the bytes a frame hands on, from
/// where they landed (a sink that copies each band's rows out, timed
/// inside the sink).
double memcpy_ms_of(sbrt_gl::GpuRenderer &on_gpu, const Camera &camera, unsigned threads,
                    int repeat)
{
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    std::vector<uint8_t> to(pixels * 3);
    double memcpy_ms = INFINITY;
    for (int k = 0; k < repeat; ++k) {
        double ms = 0;
        on_gpu.render(camera, {},
                      [&](const Band &band) {
                          const auto start = Clock::now();
                          const size_t row_bytes = size_t(band.cols) * 3;
                          for (int r = 0; r < band.rows; ++r)
                              std::memcpy(to.data() + size_t(band.first_row + r) * row_bytes,
                                          band.rgb.row(r), row_bytes);
                          ms += std::chrono::duration<double, std::milli>(Clock::now() - start)
                                    .count();
                      },
                      threads);
        memcpy_ms = std::min(memcpy_ms, ms);
    }
    return memcpy_ms;
}

/// Where the time of a GPU frame goes, face normals, best of `repeat`
/// frames with GL time queries: each pass's GPU time, the host's time after
/// the GPU was done with the last band (against one memcpy of the output
/// bytes), and the bytes the host touched per pixel.
void print_gpu_frame_parts(sbrt_gl::GpuRenderer &on_gpu, Renderer &renderer,
                           const Camera &camera, const BandSink &sink, unsigned threads,
                           int repeat, const std::string &label)
{
    sbrt_gl::GpuTracer &gpu = on_gpu.gpu();
    Shading face = renderer.shading();
    face.normals = Normals::face;
    renderer.set_shading(face);
    gpu.time_passes(true);
    sbrt_gl::GpuFrameReport best;
    best.host_after_ms = INFINITY;
    std::vector<double> pass_ms;
    warm_up_gpu(on_gpu, camera, sink, threads);
    for (int k = 0; k < repeat; ++k) {
        sbrt_gl::GpuFrameReport r = on_gpu.render(camera, {}, sink, threads);
        if (r.host_after_ms < best.host_after_ms)
            best = r;
        pass_ms.resize(r.gpu.pass_ms.size(), INFINITY);
        for (size_t p = 0; p < r.gpu.pass_ms.size(); ++p)
            pass_ms[p] = std::min(pass_ms[p], r.gpu.pass_ms[p]);
    }
    gpu.time_passes(false);
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    const double memcpy_ms = memcpy_ms_of(on_gpu, camera, threads, repeat);
    std::string passes;
    for (size_t p = 0; p < pass_ms.size(); ++p)
        if (pass_ms[p] > 0)
            passes += std::string(" gl_") + sbrt_gl::pass_name(int(p)) + "_ms=" +
                      std::to_string(pass_ms[p]);
    std::printf("gpu_parts label=%s cols=%d rows=%d bands=%d%s sink_ms=%.3f host_after_ms=%.3f "
                "memcpy_ms=%.3f host/memcpy=%.2f host_bytes_per_pixel=%.3f "
                "asked_bytes_per_pixel=3 over_budget=%zu borehole_tiles=%zu/%zu borehole_list_ms=%.3f "
                "borehole_submit_ms=%.3f gpu_wait_ms=%.3f before_dispatch_ms=%.3f "
                "parts_frame_ms=%.3f\n",
                label.c_str(), camera.cols(), camera.rows(), best.gpu.bands, passes.c_str(),
                best.render.sink_ms, best.host_after_ms, memcpy_ms, best.host_after_ms / memcpy_ms,
                double(best.gpu.host_bytes) / double(pixels), best.gpu.over_budget,
                best.gpu.borehole_tiles, best.gpu.tiles, best.gpu.borehole_list_ms,
                best.gpu.borehole_submit_ms,
                best.gpu.trace_ms - best.gpu.borehole_list_ms - best.gpu.borehole_submit_ms,
                best.gpu.before_dispatch_ms, best.render.ms);
}

} // namespace

void run_gpu_frame(const Bench &bench)
{
    const Args &args = bench.args;
    const Camera &camera = bench.camera;
    const int repeat = bench.repeat;
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    Model model = load(bench.dir, args);
    Scene scene = boreholes(model, args);
    const size_t drilled = scene.boreholes.size();
    Renderer renderer(std::move(model), bench.zexag, std::move(scene), Shading{},
                      RenderSettings{threads, true, 0});
    const std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    if (!context) {
        std::printf("gpu_frame label=%s no_gl_context\n", label.c_str());
        return;
    }
    sbrt_gl::GpuRenderer on_gpu(*context, renderer);
    const sbrt_gl::GpuTracer &gpu = on_gpu.gpu();
    const double upload_ms = gpu.stats().upload_ms;
    size_t checksum = 0;
    const BandSink sink = checksum_sink(checksum);
    Shading face = renderer.shading(), kernel = face;
    kernel.normals = Normals::kernel;
    double dispatch_ms[2] = {INFINITY, INFINITY}; // face, kernel: the best
    const auto gpu_run = [&](const Shading &shading, double &best_dispatch) {
        renderer.set_shading(shading);
        const sbrt_gl::GpuFrameReport r = on_gpu.render(camera, {}, sink, threads);
        if (!r.shaded_on_gpu)
            fail("gpu_frame: the GPU did not shade the frame");
        best_dispatch = std::min(best_dispatch, r.gpu.trace_ms);
    };
    // each kind's frames back to back (warm_up_gpu), the GPU's after 0.3 s
    // of them
    const auto gpu_best = [&](const Shading &shading, double &best_dispatch) {
        renderer.set_shading(shading);
        warm_up_gpu(on_gpu, camera, sink, threads);
        return best_ms(repeat, [&] { gpu_run(shading, best_dispatch); });
    };
    // cpu=0: the GPU's frames alone (e.g. while its clock is sampled)
    const bool cpu = args.get("cpu", "1") != "0";
    std::vector<double> ms = {gpu_best(face, dispatch_ms[0]),
                              cpu ? best_ms(repeat, [&] {
                                  renderer.set_shading(face);
                                  renderer.render(camera, {}, sink);
                              })
                                  : NAN};
    // with boreholes the CPU finds kernel normals
    ms.push_back(drilled == 0 ? gpu_best(kernel, dispatch_ms[1]) : NAN);
    const double rays = double(camera.rows()) * camera.cols();
    print_gpu_frame_parts(on_gpu, renderer, camera, sink, threads, repeat, label);
    // the GPU's image against the CPU's (face normals)
    renderer.set_shading(face);
    const size_t apart = pixels_apart(on_gpu.render_image(camera, {}, threads).rgb,
                                      renderer.render_image(camera, {}).rgb);
    std::printf("gpu_frame label=%s boreholes=%zu renderer=\"%s\" cols=%d rows=%d upload_ms=%.1f "
                "programs_ms=%.1f frame_ms=%.2f dispatch_ms=%.2f mrays=%.0f frames_per_s=%.1f "
                "cpu_frame_ms=%.1f cpu_threads=%u gpu/cpu=%.1f kernel_frame_ms=%.2f "
                "kernel_dispatch_ms=%.2f kernel/face_dispatch=%.2f pixels_apart_from_cpu=%zu "
                "(checksum %zu)\n",
                label.c_str(), drilled, gpu.gl_renderer().c_str(), camera.cols(), camera.rows(),
                upload_ms, gpu.stats().programs_ms, ms[0], dispatch_ms[0], rays / ms[0] / 1000,
                1000 / ms[0], ms[1], thread_count(threads), ms[1] / ms[0], ms[2], dispatch_ms[1],
                dispatch_ms[1] / dispatch_ms[0], apart, checksum);
}

} // namespace trace_bench
