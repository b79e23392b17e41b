/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The hit records' pass (shaders/records.comp): first hits of
 *            rows of an image written on the GPU in bands that fit a
 *            storage buffer, read back and decoded on the host, the rays
 *            over the loop budget traced there
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_RECORD_PASS_HPP
#define SBRT_GL_GPU_RECORD_PASS_HPP

#include <optional>
#include <vector>

#include "gl_objects.hpp"
#include "gpu_pass_context.hpp"
#include "gpu/gpu_layout.hpp"
#include "scene/camera.hpp"
#include "tracing/hit_image.hpp"

namespace sbrt_gl {

/// \brief The hit records' pass: a band's records on the GPU (binding 2)
/// and all of the rows' on the host. Holds a reference to the tracer's
/// PassContext; the context must be current.
class GpuRecordPass {
public:
    explicit GpuRecordPass(const PassContext &passes) : passes_(passes) {}

    /// Hits of rows [first, first + count) of `camera`'s image (the rays
    /// of the whole image), row-major into `out`, with `view` (its first
    /// pass done) and the model bound; records decoded on `cpu_threads`
    /// threads. A paged model's band goes again as its missed blocks come
    /// up (PassContext::band_again).
    void trace(const sbrt::Camera &camera, sbrt::GpuView &view, int first, int count,
               sbrt::Hit *out, unsigned cpu_threads);

private:
    /// The records' program over rows [first, first + count), in bands
    /// that fit band_, each band's records read back into records_.
    void dispatch(const sbrt::Camera &camera, sbrt::GpuView &view, int first, int count);
    /// records_ decoded into `out`; the rays over the loop budget traced
    /// on the host.
    void decode(const sbrt::Camera &camera, int first, int count, sbrt::Hit *out,
                unsigned cpu_threads);

    const PassContext &passes_;
    std::optional<GlBuffer> band_; ///< the hit records of a band of rows
    std::vector<sbrt::GpuPixelHit> records_; ///< ...of all the rows asked for
};

} // namespace sbrt_gl

#endif
