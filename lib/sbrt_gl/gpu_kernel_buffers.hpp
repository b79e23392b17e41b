/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What the kernel normals' passes keep on the GPU for a camera
 *            (shaders/kernel_*.comp): the whole image's hit records and
 *            view depths, the kernel's cells and its Kernel block, and with
 *            smoothing each hit's normal and their sums along the rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_KERNEL_BUFFERS_HPP
#define SBRT_GL_GPU_KERNEL_BUFFERS_HPP

#include <optional>

#include "gl_objects.hpp"
#include "gpu/gpu_layout.hpp"
#include "scene/camera.hpp"
#include "shading/shading.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

/// \brief The kernel passes' buffers, grown to the largest image met.
/// Holds a reference to the GL; the context must be current.
class GpuKernelBuffers {
public:
    explicit GpuKernelBuffers(const GlApi &gl) : gl_(gl) {}

    /// Room for the hit records and depths of an image of `pixels`; its
    /// hit records bound where the records pass writes them (binding 2).
    void bind_image_records(size_t pixels);
    /// The kernel of `camera` and `shading` (its cells, the smoothing's
    /// weights where shading.smooth > 0, the Kernel block) uploaded, and
    /// with smoothing room for the normals of `pixels`.
    void set_kernel(const sbrt::Tracer &tracer, const sbrt::Camera &camera,
                    const sbrt::Shading &shading, size_t pixels);
    bool smoothing() const { return kernel_.counts[3] > 0; }
    /// What the kernel passes read: the Kernel block (binding 2), the hit
    /// records (0), the depths (1), the cells (4); with smoothing the
    /// normals (3) and their sums (6).
    void bind() const;
    /// The Kernel block for a dispatch over rows [first, first + count).
    void set_rows(int first, int count);

private:
    const GlApi &gl_;
    std::optional<GlBuffer> image_hits_, depths_, cells_, block_, normals_, across_;
    sbrt::GpuKernel kernel_{};
};

} // namespace sbrt_gl

#endif
