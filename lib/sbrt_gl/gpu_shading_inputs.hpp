/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What the shading passes read beside the model: the Shade
 *            block, a drape's surface and texture, colours by voxel and
 *            the rays in double they are placed with; each made and
 *            uploaded where it changed, and bound
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_SHADING_INPUTS_HPP
#define SBRT_GL_GPU_SHADING_INPUTS_HPP

#include <optional>
#include <string>

#include "gl_objects.hpp"
#include "gpu/gpu_layout.hpp"
#include "gpu_model.hpp"
#include "scene/camera.hpp"
#include "shading/shading.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

struct GpuStats;

/// \brief The shading's inputs on the GPU (GpuTracer's shading passes).
/// Holds references to its arguments; the context must be current.
class GpuShadingInputs {
public:
    GpuShadingInputs(const GlApi &gl, const sbrt::Tracer &tracer, GpuModel &model,
                     size_t max_block_bytes);

    /// Uploads `shade` and binds it (binding 1), the materials' looks, the
    /// drape or the colours by voxel (binding 7: a scene has one or the
    /// other) and the overlays the pass shades; the drape and the colours
    /// made and uploaded where they changed (their times in `stats`).
    void bind(const sbrt::GpuShade &shade, const sbrt::Shading &shading, GpuStats &stats);
    /// Colours by voxel: the rays of `camera` in double (binding 3), so
    /// that a hit near a voxel's edge is placed on its face as the CPU
    /// places it.
    void bind_double_rays(const sbrt::Camera &camera);

private:
    const GlApi &gl_;
    const sbrt::Tracer &tracer_;
    GpuModel &model_;
    size_t max_block_bytes_;
    std::optional<GlBuffer> shade_; ///< the Shade block
    /// the drape's surface and texture, and whose they are
    std::optional<GlBuffer> drape_;
    const sbrt::Drape *drape_on_gpu_ = nullptr;
    /// colours by voxel (a property or a fade): their words with their key
    std::optional<GlBuffer> paint_;
    std::string paint_key_;
    std::optional<GlBuffer> view_double_; ///< the rays in double
};

} // namespace sbrt_gl

#endif
