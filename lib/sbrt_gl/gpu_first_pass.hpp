/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The coarse first pass on the GPU (shaders/first_pass.comp):
 *            the tiles' first-hit bounds of a camera, computed once and
 *            read by every band's ray casting
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_FIRST_PASS_HPP
#define SBRT_GL_GPU_FIRST_PASS_HPP

#include <optional>
#include <vector>

#include "gl_objects.hpp"
#include "gpu_pass_context.hpp"
#include "gpu/gpu_layout.hpp"
#include "scene/camera.hpp"

namespace sbrt_gl {

/// \brief The first pass: its tiles' bounds (binding 8) and the view they
/// are of, kept while the camera stays. Holds a reference to the tracer's
/// PassContext; the context must be current.
class GpuFirstPass {
public:
    explicit GpuFirstPass(const PassContext &passes) : passes_(passes) {}

    /// The view block of `camera`, with the first pass's tile bounds on
    /// the GPU (computed when the camera is not the last one's; no first
    /// pass without a pyramid).
    sbrt::GpuView view(const sbrt::Camera &camera, uint32_t loop_budget);
    /// The tiles' bounds at binding 8, where there are any.
    void bind() const;
    /// The bounds of the last camera traced, per tile row-major (read
    /// back; tests).
    std::vector<float> tile_starts() const;

private:
    const PassContext &passes_;
    std::optional<GlBuffer> tile_starts_;
    /// the view of tile_starts_ (rows and budget zeroed)
    sbrt::GpuView starts_view_{};
};

} // namespace sbrt_gl

#endif
