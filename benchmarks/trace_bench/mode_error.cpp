/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   trace_bench error: time against error. The exact method
 *            (face normals, then kernel normals k = 3..11, and the GL path
 *            where a context opens), the sampled one (steps 1..1/16 cell)
 *            and the adaptive one, each against the exact CPU reference
 *            with face normals; classes=FILE writes the reference's class
 *            ids (int32, row-major).
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_tracer.hpp"
#include "modes.hpp"
#include "shading/shading.hpp"
#include "tracing/cpu_tracing.hpp"
#include "tracing/sampled_tracer.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace trace_bench {

namespace {

/// Error of an image against the reference.
struct ImageError {
    double material = 0, material_off_edges = 0, rmse = 0, worst_depth = 0,
           p999_depth = 0;
};

/// Whether pixel (r, c) of the reference has a neighbour of another class.
bool on_edge(const Image &ref, int r, int c)
{
    const int rows = ref.rows, cols = ref.cols;
    const size_t i = size_t(r) * cols + c;
    for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
            const int rr = std::clamp(r + dr, 0, rows - 1);
            const int cc = std::clamp(c + dc, 0, cols - 1);
            if (ref.material[size_t(rr) * cols + cc] != ref.material[i])
                return true;
        }
    return false;
}

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
            const bool edge = on_edge(ref, r, c);
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

/// The reference's class ids, int32 row-major (NULL_CLASS: missed).
void write_classes(const std::string &path, const Image &ref)
{
    std::FILE *out = std::fopen(path.c_str(), "wb");
    if (!out || std::fwrite(ref.material.data(), sizeof(int32_t), ref.material.size(), out) !=
                    ref.material.size() || std::fclose(out) != 0)
        fail("cannot write ", path);
}

} // namespace

void run_error(const Bench &bench)
{
    const Camera &camera = bench.camera;
    const int repeat = bench.repeat;
    const Tracer tracer(bench.model, bench.zexag);
    const double size = 2 * tracer.frame().radius();
    Shading face;
    auto render = [&](HitImage hits, const Shading &s) {
        return shade(tracer, camera, std::move(hits), s);
    };
    const Image ref = render(trace_image(tracer, camera), face);
    if (const std::string path = bench.args.get("classes", ""); !path.empty())
        write_classes(path, ref);
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
    if (std::unique_ptr<sbrt_gl::GlContext> context = gl_context(bench.args)) {
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

} // namespace trace_bench
