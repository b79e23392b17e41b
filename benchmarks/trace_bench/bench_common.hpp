/****************************************************************************
 * MODULE:    benchmarks/trace_bench (r3.sbrt addon)
 * PURPOSE:   What every mode of trace_bench shares: the key=value
 *            arguments, the model less hide=, the camera of position=/
 *            target= or azimuth=/elevation=, wall-time helpers (best of N,
 *            in turns), the GL context of gpu= and its warm-up, a
 *            checksumming band sink and the pixels two images have apart.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TRACE_BENCH_COMMON_HPP
#define SBRT_TRACE_BENCH_COMMON_HPP

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "gl_context.hpp"
#include "model/model.hpp"
#include "output/band.hpp"
#include "scene/camera.hpp"

namespace sbrt_gl {
class GpuRenderer;
}

namespace trace_bench {

using Clock = std::chrono::steady_clock;

/// The command line's key=value words.
struct Args {
    std::map<std::string, std::string> values;
    std::string get(const std::string &key, const std::string &fallback) const;
    /// A comma-separated list of numbers (empty when the key is absent).
    std::vector<double> numbers(const std::string &key) const;
    /// x,y,z; throws otherwise.
    glm::dvec3 point(const std::string &key) const;
};

/// argv[first..argc) as key=value; throws on a word without '='.
Args parse_args(int argc, char *argv[], int first);

/// What a mode is given: the SBRT's directory and the arguments; the
/// model (less hide=) and the camera of the view modes (see Mode).
struct Bench {
    std::string dir;
    Args args;
    double zexag = 1;
    int repeat = 3;
    sbrt::Model model; ///< empty for the streamed modes, which load it themselves (timed)
    sbrt::Camera camera;
};

/// Wall time (ms) of one run of f.
double run_ms(const std::function<void()> &f);
/// Best wall time (ms) of `repeat` runs of f.
double best_ms(int repeat, const std::function<void()> &f);
/// Best wall times (ms) of `repeat` runs of each function, taken in turns,
/// so that a busy spell of a shared machine slows them all alike.
std::vector<double> best_ms_in_turns(int repeat,
                                     const std::vector<std::function<void()>> &functions);

/// The model, less the classes of hide=.
sbrt::Model load(const std::string &dir, const Args &args);

/// The camera of the arguments on `model` (whose frame places it):
/// position= and target= (fov= 25), or azimuth= and elevation= framing the
/// whole model as r3.sbrt.render's azimuth= does (fov= 40); rows= 884,
/// cols= 1056.
sbrt::Camera camera_of(const Args &args, const sbrt::Model &model, double zexag);

/// The GL context of gpu= (egl, osmesa; none or a failure: null, the
/// failure on stderr).
std::unique_ptr<sbrt_gl::GlContext> gl_context(const Args &args);

/// Frames on the GPU back to back for 0.3 s: a GPU's clocks fall between
/// short frames with idle time around them, so its frames are timed back
/// to back after these.
void warm_up_gpu(sbrt_gl::GpuRenderer &on_gpu, const sbrt::Camera &camera,
                 const sbrt::BandSink &sink, unsigned threads);

/// A band sink adding every 61st byte of each row's RGB to `checksum`.
sbrt::BandSink checksum_sink(size_t &checksum);

/// Pixels whose colour differs by more than one level in any component.
size_t pixels_apart(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b);

} // namespace trace_bench

#endif
