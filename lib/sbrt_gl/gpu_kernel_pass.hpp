/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Image-space kernel normals on the GPU (shaders/kernel_*.comp):
 *            the whole image's hit records and view depths kept on the
 *            GPU, then the kernel normals and shading of each band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_KERNEL_PASS_HPP
#define SBRT_GL_GPU_KERNEL_PASS_HPP

#include "gpu_kernel_buffers.hpp"
#include "gpu_pass_context.hpp"
#include "gpu_shading_inputs.hpp"
#include "gpu/gpu_layout.hpp"
#include "scene/camera.hpp"
#include "shading/shading.hpp"

namespace sbrt_gl {

/// \brief The kernel normals' passes: the records of the whole image, the
/// depth, normals and across passes, and the shading of a band, with
/// their buffers (GpuKernelBuffers). Holds references to its arguments;
/// the context must be current.
class GpuKernelPass {
public:
    GpuKernelPass(const PassContext &passes, GpuShadingInputs &shading_inputs)
        : passes_(passes), shading_inputs_(shading_inputs), buffers_(passes.gl)
    {
    }

    /// Whether the hit records of `camera`'s whole image fit one storage
    /// buffer (and the camera is not a window of a larger image), and the
    /// GPU writes them (not for boreholes and curtains alone).
    bool fits(const sbrt::Camera &camera) const;
    /// With `view` (its first pass done) and the model bound: the hit
    /// records of `camera`'s whole image and their view depths (with
    /// smoothing, the normals and their sums along the rows), kept on the
    /// GPU. False where a paged model's blocks found no room in the atlas,
    /// or its atlas is crowded (GpuPageAtlas::crowded).
    bool prepare(const sbrt::Camera &camera, const sbrt::Shading &shading, sbrt::GpuView view);
    /// The kernel's shading program of `shading` in use, with the view
    /// block of `camera`, `shade` and the kernel's buffers bound.
    void begin_shading(const sbrt::Camera &camera, const sbrt::Shading &shading,
                       const sbrt::GpuShade &shade, uint32_t loop_budget);
    /// Queues the shading of rows [first, first + count) of `camera`'s
    /// image.
    void dispatch_shading(const sbrt::Camera &camera, int first, int count);

private:
    const PassContext &passes_;
    GpuShadingInputs &shading_inputs_;
    GpuKernelBuffers buffers_;
};

} // namespace sbrt_gl

#endif
