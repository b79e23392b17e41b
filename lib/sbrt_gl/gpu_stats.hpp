/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The figures of a GPU tracer's frames (GpuStats), which its
 *            passes add to
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_STATS_HPP
#define SBRT_GL_GPU_STATS_HPP

#include <cstddef>
#include <vector>

namespace sbrt_gl {

/// Figures of the last trace_image call (or of the trace_rows calls since
/// reset_stats).
struct GpuStats {
    double upload_ms = 0;   ///< model upload
    /// Of upload_ms: the host's time making the colours by voxel
    /// (make_gpu_paint), before they go up (kept as upload_ms is).
    double paint_ms = 0;
    double trace_ms = 0;    ///< dispatches until the GPU is done
    double readback_ms = 0; ///< hit records back and decoded; shaded
                            ///< bands' rays over the budget traced here
    size_t over_budget = 0; ///< rays traced again on the CPU
    int bands = 0;
    /// Bytes of the shaded bands the host read or wrote: the outputs
    /// handed to the sink, the counts of rays over the budget and what
    /// the host wrote for those rays.
    size_t host_bytes = 0;
    /// Boreholes with the model: the 8 x 8 tiles the boreholes' pass
    /// shaded again, of all the tiles of the bands.
    size_t borehole_tiles = 0, tiles = 0;
    /// The host's time writing the head of each band's list of those
    /// tiles, which the GPU fills (or, where a box lies partly behind the
    /// camera, listing every tile).
    double borehole_list_ms = 0;
    /// The host's time dispatching the culling and the boreholes' pass (a
    /// driver that waits for the GPU shows here).
    double borehole_submit_ms = 0;
    /// The host's time from the frame's start to its first shading
    /// dispatch (the scene's lists, layouts and bindings).
    double before_dispatch_ms = 0;
    /// The host's time building programs so far (as upload_ms, the
    /// tracer's whole life): compiled by the driver, or loaded from the
    /// program cache.
    double programs_ms = 0;
    /// Bands the model pass shaded (every band but where a borehole's box
    /// holds the camera).
    int model_pass_bands = 0;
    /// A paged model: dispatches run again once the blocks their rays
    /// missed were brought up, and the host's time finding and bringing
    /// them (GpuPageAtlas).
    int page_passes = 0;
    double page_ms = 0;
    /// GPU time of each pass (GL_TIME_ELAPSED; with GpuTracer::time_passes),
    /// indexed by Pass (gpu_internal.hpp): see pass_name.
    std::vector<double> pass_ms;
};

/// The name of pass `k` of GpuStats::pass_ms.
const char *pass_name(int k);

} // namespace sbrt_gl

#endif
