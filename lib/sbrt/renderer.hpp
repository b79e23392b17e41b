/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The streamed render pipeline: a prepared scene rendered from
 *            any number of cameras, band by band (trace, shade, emit), with
 *            buffers of a band, never an image of hit records
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_RENDERER_HPP
#define SBRT_RENDERER_HPP

#include <memory>
#include <mutex>
#include <vector>

#include "output/band.hpp"
#include "output/band_writer.hpp"
#include "tracing/cpu_tracing.hpp"
#include "shading/shading.hpp"
#include "util/worker_pool.hpp"

namespace sbrt {

/// \brief How a render runs (not what it shows).
struct RenderSettings {
    unsigned threads = 0;  ///< 0: all cores
    bool first_pass = true; ///< the coarse first pass (with skipping)
    int band_rows = 0;     ///< rows per band; 0: chosen from the threads
};

/// \brief What one render did.
struct RenderReport {
    FirstPassReport first_pass; ///< (the CPU tracer only)
    int bands = 0, band_rows = 0;
    /// Most rows of hits held at once (a band, or the kernel's window).
    int most_rows_held = 0;
    double ms = 0;       ///< prepare, trace, shade and emit, the sink included
    double trace_ms = 0; ///< tracing and shading the bands (this thread)
    double sink_ms = 0;  ///< the sink's time (its own thread, overlapping)
    /// The CPU tracer (face normals): per worker, the time spent finding
    /// the first pass's bounds, tracing and shading rows; the rest of the
    /// frame it waited (at the first pass's end, or for a band buffer the
    /// sink held: band_wait_ms, all workers together) or took work.
    std::vector<double> worker_busy_ms;
    double band_wait_ms = 0;
};

/// \brief A prepared scene (the model after hiding and pruning, its
/// tracer with planes, overlays and pyramid, the shading) that renders
/// any camera. The pipeline, per band of rows: trace (CPU tracer, or the
/// RowTracer given, a GPU), normals (face, or the image-space kernel over
/// a window of rows around the band), shade into the outputs asked for,
/// and emit: the sink takes each band on a thread of its own while the
/// next bands are traced.
class Renderer {
public:
    Renderer(Model model, double zexag, Scene scene, Shading shading,
             RenderSettings settings = {});
    Renderer(const Renderer &) = delete;
    Renderer &operator=(const Renderer &) = delete;

    /// Renders `camera` (a whole image) band by band into `sink`; `rows`
    /// traces instead of the CPU tracer when given.
    RenderReport render(const Camera &camera, const Outputs &outputs,
                        const BandSink &sink, RowTracer *rows = nullptr) const;

    /// The same render gathered into one image (tests, benchmarks).
    Image render_image(const Camera &camera, const Outputs &outputs,
                       RowTracer *rows = nullptr) const;

    /// Another light, ambient, background or normals for the next
    /// renders (the prepared model, tracer and pyramid stay).
    void set_shading(const Shading &shading) { shading_ = shading; }

    const Model &model() const { return *model_; }
    const Tracer &tracer() const { return *tracer_; }
    const Shading &shading() const { return shading_; }
    const RenderSettings &settings() const { return settings_; }

private:
    std::unique_ptr<const Model> model_; ///< the tracer refers to it
    std::unique_ptr<const Tracer> tracer_;
    Shading shading_;
    RenderSettings settings_;
    /// kept from frame to frame (made by the first render that needs
    /// them): the CPU tracer's threads, the sink's thread and the band
    /// buffers, their memory warm; renders take turns on them
    mutable std::mutex frame_mutex_;
    mutable std::unique_ptr<WorkerPool> pool_;
    mutable std::unique_ptr<BandWriter> writer_;
    /// the frames' shader, kept while the shading stays
    mutable std::unique_ptr<KeptPixelShader> shader_;
};

/// An image of `camera`'s size for `outputs` (misses: NULL_CLASS, NaN).
Image empty_image(const Camera &camera, const Outputs &outputs);
/// A band's rows into their place in `image` (a sink gathering a frame).
void gather_band(const Band &band, Image &image);

} // namespace sbrt

#endif
