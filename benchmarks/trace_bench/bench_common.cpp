/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   What every mode of trace_bench shares (bench_common.hpp).
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "bench_common.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "format/format.hpp"
#include "gpu_renderer.hpp"
#include "scene/hidden_materials.hpp"
#include "scene/view.hpp"
#include "tracing/tracer.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace trace_bench {

std::string Args::get(const std::string &key, const std::string &fallback) const
{
    auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
}

std::vector<double> Args::numbers(const std::string &key) const
{
    std::vector<double> out;
    std::stringstream in(get(key, ""));
    for (std::string item; std::getline(in, item, ',');)
        out.push_back(std::stod(item));
    return out;
}

glm::dvec3 Args::point(const std::string &key) const
{
    const std::vector<double> v = numbers(key);
    if (v.size() != 3)
        fail(key, "= needs x,y,z");
    return {v[0], v[1], v[2]};
}

Args parse_args(int argc, char *argv[], int first)
{
    Args args;
    for (int i = first; i < argc; ++i) {
        const std::string a = argv[i];
        const size_t eq = a.find('=');
        if (eq == std::string::npos)
            fail("argument ", a, " is not key=value");
        args.values[a.substr(0, eq)] = a.substr(eq + 1);
    }
    return args;
}

double run_ms(const std::function<void()> &f)
{
    const auto start = Clock::now();
    f();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double best_ms(int repeat, const std::function<void()> &f)
{
    double best = INFINITY;
    for (int i = 0; i < repeat; ++i)
        best = std::min(best, run_ms(f));
    return best;
}

std::vector<double> best_ms_in_turns(int repeat,
                                     const std::vector<std::function<void()>> &functions)
{
    std::vector<double> best(functions.size(), INFINITY);
    for (int i = 0; i < repeat; ++i)
        for (size_t k = 0; k < functions.size(); ++k)
            best[k] = std::min(best[k], run_ms(functions[k]));
    return best;
}

Model load(const std::string &dir, const Args &args)
{
    // paged=MB: opened as the modules open it, its blocks decoded as the
    // rays reach them within MB
    const std::string paged_mb = args.get("paged", "");
    std::optional<Model> paged;
    if (!paged_mb.empty()) {
        Paging paging;
        paging.budget_bytes = uint64_t(std::stoull(paged_mb)) << 20;
        paged = read_sbrt_paged(dir, paging);
        if (!paged)
            fail("paged=: ", dir, " is not a paged model (format 2.1)");
    }
    Model m = paged ? std::move(*paged) : read_sbrt(dir);
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

Camera camera_of(const Args &args, const Model &model, double zexag)
{
    const Tracer probe(model, zexag);
    const int rows = std::stoi(args.get("rows", "884")),
              cols = std::stoi(args.get("cols", "1056"));
    if (args.get("azimuth", "").empty())
        return Camera::perspective(probe.frame().exaggerated_from_map(args.point("position")),
                                   probe.frame().exaggerated_from_map(args.point("target")),
                                   std::stod(args.get("fov", "25")), rows, cols);
    View view;
    view.azimuth = std::stod(args.get("azimuth", "225"));
    view.elevation = std::stod(args.get("elevation", "30"));
    view.fov = std::stod(args.get("fov", "40"));
    return view_camera(view, model, probe.frame(), rows, cols);
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

/// (at its idle clock a data-centre GPU runs the same pass several times
/// slower)
void warm_up_gpu(sbrt_gl::GpuRenderer &on_gpu, const Camera &camera, const BandSink &sink,
                 unsigned threads)
{
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::milliseconds(300))
        on_gpu.render(camera, {}, sink, threads);
}

BandSink checksum_sink(size_t &checksum)
{
    return [&checksum](const Band &band) {
        for (int r = 0; r < band.rows; ++r)
            for (size_t i = 0; i < size_t(band.cols) * 3; i += 61)
                checksum += band.rgb.row(r)[i];
    };
}

size_t pixels_apart(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b)
{
    size_t apart = 0;
    for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
        apart += std::abs(int(a[i]) - b[i]) > 1 || std::abs(int(a[i + 1]) - b[i + 1]) > 1 ||
                 std::abs(int(a[i + 2]) - b[i + 2]) > 1;
    return apart;
}

} // namespace trace_bench
