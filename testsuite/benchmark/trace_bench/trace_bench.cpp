/****************************************************************************
 * MODULE:    testsuite/benchmark/trace_bench (r3.sbrt addon)
 * PURPOSE:   In-process timings on an SBRT file, best of `repeat`:
 *              skipping  the exact tracer with and without empty-space
 *                        skipping, and with skipping but without the
 *                        coarse first pass (and on the GPU where a
 *                        context opens)
 *              frame     the streamed pipeline in process: load, prepare
 *                        (Renderer), a whole frame (trace, shade, the RGB
 *                        bands handed to a sink), warm, on threads= (0:
 *                        all cores); beside it the whole-image reference
 *                        (trace_image, then shade)
 *              gpu_frame the streamed frame on the GPU (gpu=, default
 *                        egl): the model uploaded once; traced, shaded
 *                        (face, then kernel normals) and the RGB read back,
 *                        warm, each kind back to back (the GPU's after 0.3 s
 *                        of frames: its clocks fall between short frames);
 *                        beside them the CPU's frame (threads=), and the
 *                        pixels of the GPU's image apart from the CPU's
 *              paint_frame the class view against a property (property=
 *                        a+b: their sum through a ramp) and a fade
 *                        (fade=c, 0..100) on the GPU (gpu=) and the CPU:
 *                        each kind's first frame of a fresh GPU renderer
 *                        and channels (the colours by voxel made and
 *                        uploaded; and coloured on the host at the GPU's
 *                        hits instead), its warm frame, whether the GPU shaded
 *                        it, and the pixels whose colour differs from the
 *                        CPU's by more than one level
 *              row_order on one thread, the rows in the order one of
 *                        as_threads= (16) threads meets them, a row a take,
 *                        in runs (ROWS_PER_TAKE) and in runs traced block
 *                        by block (COLS_PER_BLOCK), against the image's
 *                        own order
 *              format    the stacks file in format 1 and 2: bytes, bytes
 *                        per interval, load (warm) and write times
 *              error     time against error: the exact method, the sampled
 *                        one (steps 1..1/16 cell, adaptive), kernel
 *                        normals k = 3..11, each against the exact CPU
 *                        reference with face normals
 * USAGE:     trace_bench format SBRT_DIR [repeat=7] [label=name]
 *            trace_bench skipping|frame|gpu_frame|error|row_order SBRT_DIR position=x,y,z
 *            target=x,y,z [fov=25] [zexag=1] [cols=1056] [rows=884]
 *            [repeat=3] [hide=id,id] [label=name] [gpu=egl|osmesa|none]
 *            [threads=N] [classes=FILE: error writes the reference's class
 *            ids, int32] [boreholes=N radius=R: gpu_frame with N boreholes]
 *            [property=a+b fade=c: paint_frame] [cpu=0: gpu_frame without
 *            the CPU's frames]; instead of position=,
 *            azimuth= and elevation= (degrees) frame the whole model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "tracing/cpu_tracing.hpp"
#include "format/atomic_dir.hpp"
#include "util/error.hpp"
#include "format/format.hpp"
#include "gpu_renderer.hpp"
#include "gpu_tracer.hpp"
#include "scene/hidden_materials.hpp"
#include "shading/property_paint.hpp"
#include "scene/view.hpp"
#include "util/parallel.hpp"
#include "renderer.hpp"
#include "tracing/sampled_tracer.hpp"
#include "shading/shading.hpp"

using namespace sbrt;

namespace {

using Clock = std::chrono::steady_clock;

struct Args {
    std::map<std::string, std::string> values;
    std::string get(const std::string &key, const std::string &fallback) const
    {
        auto it = values.find(key);
        return it == values.end() ? fallback : it->second;
    }
    std::vector<double> numbers(const std::string &key) const
    {
        std::vector<double> out;
        std::stringstream in(get(key, ""));
        for (std::string item; std::getline(in, item, ',');)
            out.push_back(std::stod(item));
        return out;
    }
    glm::dvec3 point(const std::string &key) const
    {
        const std::vector<double> v = numbers(key);
        if (v.size() != 3)
            fail(key, "= needs x,y,z");
        return {v[0], v[1], v[2]};
    }
};

/// Wall time (ms) of one run of f.
double run_ms(const std::function<void()> &f)
{
    const auto start = Clock::now();
    f();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Best wall time (ms) of `repeat` runs of f.
double best_ms(int repeat, const std::function<void()> &f)
{
    double best = INFINITY;
    for (int i = 0; i < repeat; ++i)
        best = std::min(best, run_ms(f));
    return best;
}

/// Best wall times (ms) of `repeat` runs of each function, taken in turns,
/// so that a busy spell of a shared machine slows them all alike.
std::vector<double> best_ms_in_turns(int repeat,
                                     const std::vector<std::function<void()>> &functions)
{
    std::vector<double> best(functions.size(), INFINITY);
    for (int i = 0; i < repeat; ++i)
        for (size_t k = 0; k < functions.size(); ++k)
            best[k] = std::min(best[k], run_ms(functions[k]));
    return best;
}

/// The model, less the classes of hide=.
Model load(const std::string &dir, const Args &args)
{
    Model m = read_sbrt(dir);
    std::vector<uint32_t> hidden;
    for (double id : args.numbers("hide")) {
        const int64_t k = m.find_material(int32_t(id));
        if (k < 0)
            fail("hide: no class ", id);
        hidden.push_back(uint32_t(k));
    }
    if (hidden.empty())
        return m; // moved, not copied
    return hide_materials(m, hidden);
}

std::unique_ptr<sbrt_gl::GlContext> gl_context(const Args &args)
{
    const std::string name = args.get("gpu", "egl");
    if (name == "none")
        return nullptr;
    try {
        return sbrt_gl::create_gl_context(name);
    }
    catch (const Error &e) {
        std::fprintf(stderr, "no GL context (%s): %s\n", name.c_str(), e.what());
        return nullptr;
    }
}

void skipping(const Model &model, const Args &args, const Camera &camera,
              double zexag, int repeat)
{
    const std::string label = args.get("label", "view");
    const double rays = double(camera.rows()) * camera.cols();
    std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    Scene no_skipping;
    no_skipping.skip_empty_space = false;
    const Tracer plain(model, zexag, no_skipping), skipping(model, zexag);
    // skipping off; on without the coarse first pass; on with it
    const std::vector<double> ms = best_ms_in_turns(
        repeat, {[&] { trace_image(plain, camera); },
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
    if (!context)
        return;
    // the GL path on the same view, in both memory layouts: `auto` picks
    // the faster of it and the CPU
    for (GpuLayout layout : {GpuLayout::ssbo, GpuLayout::textures}) {
        sbrt_gl::GpuTracer gpu_plain(*context, plain, layout);
        sbrt_gl::GpuTracer gpu(*context, skipping, layout);
        const std::vector<double> gl_ms =
            best_ms_in_turns(repeat, {[&] { gpu_plain.trace_image(camera); },
                                      [&] { gpu.trace_image(camera); }});
        const double gl_off = gl_ms[0], gl_on = gl_ms[1];
        const GpuMemory &m = gpu.memory();
        std::printf("skipping view=%s backend=%s layout=%s renderer=\"%s\" ms=%.1f "
                    "Mrays/s=%.2f skipping_off_ms=%.1f off/on=%.2f gl/cpu=%.2f "
                    "gpu_bytes=%llu index_bytes=%llu interval_bytes=%llu waste_bytes=%llu "
                    "pyramid_bytes=%zu\n",
                    label.c_str(), context->name().c_str(), gpu_layout_name(layout),
                    gpu.gl_renderer().c_str(), gl_on, rays / gl_on / 1e3, gl_off,
                    gl_off / gl_on, gl_on / on_ms, (unsigned long long)m.total(),
                    (unsigned long long)m.index_bytes, (unsigned long long)m.interval_bytes,
                    (unsigned long long)m.waste_bytes, gpu.pyramid_bytes());
    }
}

/// Error of an image against the reference.
struct ImageError {
    double material = 0, material_off_edges = 0, rmse = 0, worst_depth = 0,
           p999_depth = 0;
};

ImageError image_error(const Image &ref, const Image &img, double size)
{
    ImageError e;
    const int rows = ref.rows, cols = ref.cols;
    size_t wrong = 0, wrong_inside = 0, inside = 0;
    double squares = 0;
    std::vector<double> depth;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const size_t i = size_t(r) * cols + c;
            bool edge = false;
            for (int dr = -1; dr <= 1 && !edge; ++dr)
                for (int dc = -1; dc <= 1 && !edge; ++dc) {
                    const int rr = std::clamp(r + dr, 0, rows - 1);
                    const int cc = std::clamp(c + dc, 0, cols - 1);
                    edge = ref.material[size_t(rr) * cols + cc] != ref.material[i];
                }
            const bool differs = img.material[i] != ref.material[i];
            wrong += differs;
            inside += !edge;
            wrong_inside += differs && !edge;
            for (int k = 0; k < 3; ++k) {
                const double d = double(img.rgb[3 * i + k]) - ref.rgb[3 * i + k];
                squares += d * d;
            }
            if (!differs && std::isfinite(ref.depth[i]))
                depth.push_back(std::fabs(img.depth[i] - ref.depth[i]) / size);
        }
    e.material = 100.0 * wrong / ref.material.size();
    e.material_off_edges = inside ? 100.0 * wrong_inside / inside : 0;
    e.rmse = std::sqrt(squares / (3.0 * ref.material.size()));
    if (!depth.empty()) {
        std::sort(depth.begin(), depth.end());
        e.worst_depth = depth.back();
        e.p999_depth = depth[size_t(0.999 * (depth.size() - 1))];
    }
    return e;
}

void print_error(const char *method, const std::string &setting, double ms,
                 const ImageError &e)
{
    std::printf("error method=%s setting=%s ms=%.1f material_error_pct=%.4f "
                "material_error_off_edges_pct=%.4f colour_rmse=%.3f "
                "depth_error_max=%.2e depth_error_p99.9=%.2e\n",
                method, setting.c_str(), ms, e.material, e.material_off_edges, e.rmse,
                e.worst_depth, e.p999_depth);
}

void time_against_error(const Model &model, const Args &args, const Camera &camera,
                        double zexag, int repeat)
{
    const Tracer tracer(model, zexag);
    const double size = 2 * tracer.frame().radius();
    Shading face;
    auto render = [&](HitImage hits, const Shading &s) {
        return shade(tracer, camera, std::move(hits), s);
    };
    const Image ref = render(trace_image(tracer, camera), face);
    if (const std::string path = args.get("classes", ""); !path.empty()) {
        // the reference's class ids, int32 row-major (NULL_CLASS: missed)
        std::FILE *out = std::fopen(path.c_str(), "wb");
        if (!out || std::fwrite(ref.material.data(), sizeof(int32_t), ref.material.size(),
                                out) != ref.material.size() || std::fclose(out) != 0)
            fail("cannot write ", path);
    }
    // exact, face normals (the reference itself: its time)
    Image img;
    double ms = best_ms(repeat, [&] { img = render(trace_image(tracer, camera), face); });
    print_error("exact", "face", ms, image_error(ref, img, size));
    for (int k = 3; k <= 11; k += 2) {
        Shading kernel = face;
        kernel.normals = Normals::kernel;
        kernel.kernel = k;
        ms = best_ms(repeat, [&] { img = render(trace_image(tracer, camera), kernel); });
        print_error("exact", "kernel" + std::to_string(k), ms, image_error(ref, img, size));
    }
    if (std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args)) {
        sbrt_gl::GpuTracer gpu(*context, tracer);
        ms = best_ms(repeat, [&] { img = render(gpu.trace_image(camera), face); });
        print_error("exact_gl", "face", ms, image_error(ref, img, size));
    }
    for (int inverse : {1, 2, 4, 8, 16}) {
        const Sampling s{1.0 / inverse, 0};
        ms = best_ms(repeat, [&] { img = render(sample_image(tracer, camera, s), face); });
        print_error("sampled", "1/" + std::to_string(inverse), ms, image_error(ref, img, size));
    }
    for (int inverse : {4, 16}) {
        const Sampling s{1.0, 1.0 / inverse};
        ms = best_ms(repeat, [&] { img = render(sample_image(tracer, camera, s), face); });
        print_error("adaptive", "1+1/" + std::to_string(inverse), ms,
                    image_error(ref, img, size));
    }
}

} // namespace

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

/// On one thread, the rows of the image traced in the order one of
/// `as_threads` threads meets them (thread k's takes, then thread k+1's),
/// taking one row at a time and taking runs of ROWS_PER_TAKE, against the
/// image's own order: what a thread's cache loses when its rows lie apart
/// (issue 32: at 16 threads the workers' busy time summed to 1.1-1.5
/// times one thread's), measured without the cores it needs.
void row_order(const Model &model, const Args &args, const Camera &camera, double zexag,
               int repeat)
{
    const Tracer tracer(model, zexag);
    CpuRowTracer rows(tracer, camera, 1, true);
    HitImage hits(static_cast<size_t>(camera.cols()));
    const int image_rows = camera.rows();
    const unsigned as_threads = unsigned(std::stoi(args.get("as_threads", "16")));
    // the takes of `run` rows one of `threads` threads meets, each row
    // traced whole or, `in_blocks`, the take block by block
    // (for_each_block, as the renderer does)
    const auto order = [&](unsigned threads, int run, bool in_blocks = false) {
        return [&, threads, run, in_blocks] {
            const int takes = (image_rows + run - 1) / run;
            for (unsigned t = 0; t < threads; ++t)
                for (int k = int(t); k < takes; k += int(threads)) {
                    const int first = k * run, end = std::min(image_rows, (k + 1) * run);
                    if (!in_blocks) {
                        for (int r = first; r < end; ++r)
                            rows.trace_row(r, hits.data());
                        continue;
                    }
                    for_each_block(first, end, camera.cols(), [&](int row, int c0, int c1) {
                        rows.trace_span(row, c0, c1, hits.data());
                    });
                }
        };
    };
    const int run = ROWS_PER_TAKE;
    const std::vector<double> ms =
        best_ms_in_turns(repeat, {order(1, image_rows), order(as_threads, 1), order(as_threads, run),
                                  order(as_threads, run, true)});
    std::printf("row_order label=%s cols=%d rows=%d as_threads=%u image_order_ms=%.1f "
                "a_row_a_take_ms=%.1f (%.2fx) runs_of_%d_ms=%.1f (%.2fx) "
                "runs_in_blocks_of_%d_ms=%.1f (%.2fx)\n",
                args.get("label", "view").c_str(), camera.cols(), image_rows, as_threads, ms[0],
                ms[1], ms[1] / ms[0], run, ms[2], ms[2] / ms[0], COLS_PER_BLOCK, ms[3],
                ms[3] / ms[0]);
}

/// The streamed frame in process, warm (best of `repeat`), and the
/// whole-image reference, taken in turns.
void frame(const std::string &dir, const Args &args, const Camera &camera, double zexag,
           int repeat)
{
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    Model model;
    const double load_ms = run_ms([&] { model = load(dir, args); });
    std::unique_ptr<Renderer> renderer;
    const double prepare_ms = run_ms([&] {
        renderer = std::make_unique<Renderer>(std::move(model), zexag, Scene{}, Shading{},
                                              RenderSettings{threads, true, 0});
    });
    size_t checksum = 0;
    const auto sink = [&](const Band &band) {
        for (int r = 0; r < band.rows; ++r)
            for (size_t i = 0; i < size_t(band.cols) * 3; i += 61)
                checksum += band.rgb.row(r)[i];
    };
    const Tracer &tracer = renderer->tracer();
    RenderReport best;
    best.ms = INFINITY;
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
    std::vector<double> ms = best_ms_in_turns(repeat, runs);
    ms.resize(2, NAN);
    const double rays = double(camera.rows()) * camera.cols();
    std::printf("frame label=%s threads=%u cols=%d rows=%d load_ms=%.1f prepare_ms=%.1f "
                "frame_ms=%.1f mrays=%.2f reference_ms=%.1f (checksum %zu)\n",
                label.c_str(), thread_count(threads), camera.cols(), camera.rows(),
                load_ms, prepare_ms, ms[0], rays / ms[0] / 1000, ms[1], checksum);
    print_frame_parts(best, label);
}

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

/// Pixels whose colour differs by more than one level in any component.
size_t pixels_apart(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b)
{
    size_t apart = 0;
    for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
        apart += std::abs(int(a[i]) - b[i]) > 1 || std::abs(int(a[i + 1]) - b[i + 1]) > 1 ||
                 std::abs(int(a[i + 2]) - b[i + 2]) > 1;
    return apart;
}

/// Frames on the GPU back to back for 0.3 s: a GPU's clocks fall between
/// short frames with idle time around them (an H100 ran the same pass in
/// 0.77 ms at its idle clock of 345 MHz and in 0.14 ms at 1980 MHz), so
/// its frames are timed back to back after these.
void warm_up_gpu(sbrt_gl::GpuRenderer &on_gpu, const Camera &camera, const BandSink &sink,
                 unsigned threads)
{
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::milliseconds(300))
        on_gpu.render(camera, {}, sink, threads);
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
    // one memcpy of the bytes the frame hands on, from where they landed
    // (a sink that copies each band's rows out, timed inside the sink)
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

/// The streamed frame on the GPU (gpu=egl|osmesa): the model uploaded
/// once, every frame traced, shaded (face normals, then kernel normals, not
/// with boreholes=) and its RGB bands read back into host memory, warm,
/// best of `repeat` back to back (warm_up_gpu), and the same frame on the
/// CPU (threads=).
void gpu_frame(const std::string &dir, const Args &args, const Camera &camera, double zexag,
               int repeat)
{
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    Model model = load(dir, args);
    Scene scene = boreholes(model, args);
    const size_t drilled = scene.boreholes.size();
    Renderer renderer(std::move(model), zexag, std::move(scene), Shading{},
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
    const auto sink = [&](const Band &band) {
        for (int r = 0; r < band.rows; ++r)
            for (size_t i = 0; i < size_t(band.cols) * 3; i += 61)
                checksum += band.rgb.row(r)[i];
    };
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
                upload_ms, gpu.stats().programs_ms, ms[0], dispatch_ms[0], rays / ms[0] / 1000, 1000 / ms[0], ms[1],
                thread_count(threads), ms[1] / ms[0], ms[2], dispatch_ms[1],
                dispatch_ms[1] / dispatch_ms[0], apart, checksum);
}

/// The class view, property= (a sum of channels through a ramp over their
/// stated range) and fade= (0..100) of the SBRT in `dir`, on the GPU and
/// the CPU (threads=): the first frame of a fresh GPU renderer with fresh
/// channels (nothing decoded, the colours by voxel made and uploaded; the
/// GL programs come from the cache, filled by a frame before), the warm
/// frame (best of `repeat` back to back, after 0.3 s of them) and the CPU's
/// warm frame; whether the GPU shaded and how many pixels differ from the
/// CPU's by more than one level.
void paint_frame(const std::string &dir, const Args &args, const Camera &camera, double zexag,
                 int repeat)
{
    const std::string label = args.get("label", "view");
    const unsigned threads = unsigned(std::stoi(args.get("threads", "0")));
    const Model as_read = read_sbrt(dir);
    const std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    if (!context) {
        std::printf("paint_frame label=%s no_gl_context\n", label.c_str());
        return;
    }
    // the kinds: class, property, fade (those asked for)
    struct Kind {
        std::string name, what;
    };
    std::vector<Kind> kinds{{"class", ""}};
    if (!args.get("property", "").empty())
        kinds.push_back({"property", args.get("property", "")});
    if (!args.get("fade", "").empty())
        kinds.push_back({"fade", args.get("fade", "")});
    const auto channel_of = [&](const PropertyChannels &channels, const std::string &name) {
        const int k = channels.find(name);
        if (k < 0)
            fail("no channel ", name, " in ", dir);
        return size_t(k);
    };
    // the shading of a kind over fresh channels (nothing decoded)
    struct Painted {
        std::shared_ptr<const PropertyChannels> channels;
        std::unique_ptr<PropertyPaint> property;
        std::unique_ptr<UncertaintyFade> fade;
        Shading shading;
    };
    const auto painted = [&](const Kind &kind) {
        Painted p;
        if (kind.name == "class")
            return p;
        p.channels = read_channels(dir, as_read);
        if (!p.channels)
            fail(dir, " has no property channels");
        if (kind.name == "fade") {
            p.fade = std::make_unique<UncertaintyFade>(
                as_read, p.channels, channel_of(*p.channels, kind.what), 0, 100);
            p.shading.fade = p.fade.get();
            return p;
        }
        std::vector<size_t> summed;
        double low = 0, high = 0;
        std::stringstream in(kind.what);
        for (std::string name; std::getline(in, name, '+');) {
            summed.push_back(channel_of(*p.channels, name));
            const ChannelInfo &info = p.channels->info(summed.back());
            low += std::min(info.physical(float(info.min)), info.physical(float(info.max)));
            high += std::max(info.physical(float(info.min)), info.physical(float(info.max)));
        }
        if (!(high > low))
            high = low + 1;
        const ColorRamp viridis = ColorRamp::through(
            {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}}, low,
            high);
        p.property = std::make_unique<PropertyPaint>(as_read, p.channels, summed, viridis);
        p.shading.property = p.property.get();
        return p;
    };
    Renderer renderer(read_sbrt(dir), zexag, Scene{}, Shading{}, RenderSettings{threads, true, 0});
    const double rays = double(camera.rows()) * camera.cols();
    std::map<std::string, double> warm_ms, first_ms;
    for (const Kind &kind : kinds) {
        // the GL programs into the cache (not timed)
        {
            Painted p = painted(kind);
            renderer.set_shading(p.shading);
            sbrt_gl::GpuRenderer on_gpu(*context, renderer);
            on_gpu.render(camera, {}, [](const Band &) {}, threads);
        }
        // cold: fresh channels, a fresh GPU renderer, its first frame
        Painted p = painted(kind);
        renderer.set_shading(p.shading);
        double first = 0, upload_ms = 0, paint_ms = 0;
        bool on_gpu_shaded = false;
        std::unique_ptr<sbrt_gl::GpuRenderer> on_gpu;
        first = run_ms([&] {
            on_gpu = std::make_unique<sbrt_gl::GpuRenderer>(*context, renderer);
            const sbrt_gl::GpuFrameReport r =
                on_gpu->render(camera, {}, [](const Band &) {}, threads);
            on_gpu_shaded = r.shaded_on_gpu;
        });
        upload_ms = on_gpu->gpu().stats().upload_ms;
        paint_ms = on_gpu->gpu().stats().paint_ms;
        // cold again, the host colouring at the GPU's hits (decoding only
        // the blocks rays reach)
        double first_host = NAN;
        if (kind.name != "class") {
            Painted fresh = painted(kind);
            renderer.set_shading(fresh.shading);
            first_host = run_ms([&] {
                sbrt_gl::GpuRenderer host_coloured(*context, renderer);
                host_coloured.paint_on_gpu(false);
                host_coloured.render(camera, {}, [](const Band &) {}, threads);
            });
            renderer.set_shading(p.shading);
        }
        // warm: back to back after 0.3 s of frames
        warm_up_gpu(*on_gpu, camera, [](const Band &) {}, threads);
        const double warm = best_ms(repeat, [&] {
            on_gpu->render(camera, {}, [](const Band &) {}, threads);
        });
        // where the warm frame's time goes: each pass's GL time, the rays
        // the host traced and coloured (flagged by the shader), its time
        on_gpu->gpu().time_passes(true);
        const sbrt_gl::GpuFrameReport parts =
            on_gpu->render(camera, {}, [](const Band &) {}, threads);
        on_gpu->gpu().time_passes(false);
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
        const size_t apart = pixels_apart(on_gpu->render_image(camera, {}, threads).rgb,
                                          renderer.render_image(camera, {}).rgb);
        const double cpu = best_ms(repeat, [&] { renderer.render(camera, {}, [](const Band &) {}); });
        warm_ms[kind.name] = warm;
        first_ms[kind.name] = first;
        std::printf("paint_frame label=%s kind=%s%s%s renderer=\"%s\" cols=%d rows=%d "
                    "shaded_on_gpu=%s first_frame_ms=%.2f upload_ms=%.2f paint_ms=%.2f "
                    "first_frame_host_coloured_ms=%.2f frame_ms=%.3f "
                    "mrays=%.0f cpu_frame_ms=%.1f cpu_threads=%u gpu/cpu=%.1f "
                    "pixels_apart_from_cpu=%zu of %.0f\n",
                    label.c_str(), kind.name.c_str(), kind.what.empty() ? "" : "=",
                    kind.what.c_str(), on_gpu->gpu().gl_renderer().c_str(), camera.cols(),
                    camera.rows(), on_gpu_shaded ? "yes" : "no", first, upload_ms, paint_ms, first_host,
                    warm,
                    rays / warm / 1000, cpu, thread_count(threads), cpu / warm,
                    apart, rays);
    }
    for (const Kind &kind : kinds)
        if (kind.name != "class")
            std::printf("paint_frame label=%s %s/class first_frame=%.2f warm_frame=%.2f\n",
                        label.c_str(), kind.name.c_str(), first_ms[kind.name] / first_ms["class"],
                        warm_ms[kind.name] / warm_ms["class"]);
}

/// Format 1 against format 2 on the model of `directory` (whatever its
/// own format): both written to temporary directories, each read and
/// written `repeat` times in turns.
void formats(const std::string &directory, const Args &args, int repeat)
{
    const Model model = read_sbrt(directory);
    const std::string v1 = directory + ".bench_v1", v2 = directory + ".bench_v2";
    const auto write_v1 = [&] {
        AtomicDirectory out(v1);
        out.write_file("stacks", encode_stacks_v1(model));
        out.commit();
    };
    write_v1();
    write_sbrt(v2, model, "bench");
    size_t sink = 0;
    const std::vector<double> ms = best_ms_in_turns(
        repeat, {[&] { sink += read_sbrt(v1).intervals().size(); },
                 [&] { sink += read_sbrt(v2).intervals().size(); }, write_v1,
                 [&] { write_sbrt(v2, model, "bench"); }});
    const double v1_bytes = double(read_file_bytes(v1 + "/stacks").size());
    const double v2_bytes = double(read_file_bytes(v2 + "/stacks").size());
    const double intervals = double(model.intervals().size());
    std::printf("format label=%s intervals=%.0f cells=%llu v1_bytes=%.0f v2_bytes=%.0f "
                "v1_per_interval=%.2f v2_per_interval=%.2f v1/v2=%.1f "
                "load_v1_ms=%.1f load_v2_ms=%.1f write_v1_ms=%.1f write_v2_ms=%.1f (%zu)\n",
                args.get("label", directory).c_str(), intervals,
                (unsigned long long)model.frame().cells(), v1_bytes, v2_bytes,
                v1_bytes / intervals, v2_bytes / intervals, v1_bytes / v2_bytes, ms[0], ms[1],
                ms[2], ms[3], sink);
    remove_tree(v1);
    remove_tree(v2);
}

/// The same model held compact (as read: 4-byte intervals where its tops
/// are voxel boundaries) and wide (8 bytes, a view as a v1 file gives):
/// bytes in memory and on the GPU, and the trace time of one view on the
/// CPU and the GL path, taken in turns.
void compact_against_wide(const Model &read, const Args &args, const Camera &camera,
                          double zexag, int repeat)
{
    const std::string label = args.get("label", "view");
    Intervals owned(read.intervals().size());
    auto wide_records = std::make_shared<std::vector<Interval>>(read.intervals().size());
    for (size_t i = 0; i < wide_records->size(); ++i)
        owned[i] = (*wide_records)[i] = read.intervals()[i];
    const Model wide(read.frame(), read.materials(), read.index(),
                     IntervalArray(wide_records, wide_records->data(), wide_records->size()));
    // owned intervals are packed where exact (a v1 file's view is not)
    const Model model(read.frame(), read.materials(), read.index(), std::move(owned));
    const Tracer compact_tracer(model, zexag), wide_tracer(wide, zexag);
    const std::vector<double> ms =
        best_ms_in_turns(repeat, {[&] { trace_image(compact_tracer, camera); },
                                  [&] { trace_image(wide_tracer, camera); }});
    const Stats s = model.stats();
    const double cells = double(model.frame().cells()), n = double(s.intervals);
    std::printf("compact view=%s intervals=%.0f cells=%.0f compact=%s "
                "interval_bytes_per_interval=%.2f index_bytes_per_cell=%.3f "
                "v1_memory_per_interval=8.00 v1_index_per_cell=4.00 "
                "cpu_compact_ms=%.1f cpu_wide_ms=%.1f wide/compact=%.3f\n",
                label.c_str(), n, cells, model.intervals().is_compact() ? "yes" : "no",
                double(s.interval_bytes) / n, double(s.index_bytes) / cells, ms[0], ms[1],
                ms[1] / ms[0]);
    std::unique_ptr<sbrt_gl::GlContext> context = gl_context(args);
    if (!context)
        return;
    sbrt_gl::GpuTracer gpu_compact(*context, compact_tracer, GpuLayout::ssbo);
    sbrt_gl::GpuTracer gpu_wide(*context, wide_tracer, GpuLayout::ssbo);
    const std::vector<double> gl_ms =
        best_ms_in_turns(repeat, {[&] { gpu_compact.trace_image(camera); },
                                  [&] { gpu_wide.trace_image(camera); }});
    const GpuMemory &c = gpu_compact.memory(), &w = gpu_wide.memory();
    std::printf("compact view=%s backend=%s renderer=\"%s\" gpu_interval_bytes_per_interval=%.2f "
                "gpu_index_bytes_per_cell=%.3f wide_gpu_interval_bytes_per_interval=%.2f "
                "gl_compact_ms=%.1f gl_wide_ms=%.1f wide/compact=%.3f\n",
                label.c_str(), context->name().c_str(), gpu_compact.gl_renderer().c_str(),
                double(c.interval_bytes) / n, double(c.index_bytes) / cells,
                double(w.interval_bytes) / n, gl_ms[0], gl_ms[1], gl_ms[1] / gl_ms[0]);
}

int main(int argc, char *argv[])
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s format|skipping|frame|gpu_frame|paint_frame|error|compact|row_order SBRT_DIR key=value...\n", argv[0]);
        return 2;
    }
    try {
        Args args;
        for (int i = 3; i < argc; ++i) {
            const std::string a = argv[i];
            const size_t eq = a.find('=');
            if (eq == std::string::npos)
                fail("argument ", a, " is not key=value");
            args.values[a.substr(0, eq)] = a.substr(eq + 1);
        }
        const std::string mode = argv[1];
        if (mode == "format") {
            formats(argv[2], args, std::stoi(args.get("repeat", "7")));
            return 0;
        }
        // the streamed modes load the model themselves (timed)
        const bool streamed = mode == "frame" || mode == "gpu_frame" || mode == "paint_frame";
        const Model model = streamed ? Model() : load(argv[2], args);
        const double zexag = std::stod(args.get("zexag", "1"));
        const int repeat = std::stoi(args.get("repeat", "3"));
        const Model framed = streamed ? read_sbrt(argv[2]) : Model();
        const Tracer probe(streamed ? framed : model, zexag);
        const int rows = std::stoi(args.get("rows", "884")),
                  cols = std::stoi(args.get("cols", "1056"));
        Camera camera;
        if (args.get("azimuth", "").empty())
            camera = Camera::perspective(probe.frame().exaggerate(args.point("position")),
                                         probe.frame().exaggerate(args.point("target")),
                                         std::stod(args.get("fov", "25")), rows, cols);
        else { // the whole model framed, as r3.sbrt.render's azimuth= does
            View view;
            view.azimuth = std::stod(args.get("azimuth", "225"));
            view.elevation = std::stod(args.get("elevation", "30"));
            view.fov = std::stod(args.get("fov", "40"));
            camera = view_camera(view, streamed ? framed : model, probe.frame(), rows, cols);
        }
        if (mode == "frame")
            frame(argv[2], args, camera, zexag, repeat);
        else if (mode == "gpu_frame")
            gpu_frame(argv[2], args, camera, zexag, repeat);
        else if (mode == "paint_frame")
            paint_frame(argv[2], args, camera, zexag, repeat);
        else if (mode == "skipping")
            skipping(model, args, camera, zexag, repeat);
        else if (mode == "error")
            time_against_error(model, args, camera, zexag, repeat);
        else if (mode == "row_order")
            row_order(model, args, camera, zexag, repeat);
        else if (mode == "compact")
            compact_against_wide(model, args, camera, zexag, repeat);
        else
            fail("unknown mode ", mode);
    }
    catch (const std::exception &e) {
        std::fprintf(stderr, "trace_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
