/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GPU as the streamed renderer's row tracer of one camera;
 *            the pixels whose rays may meet a borehole traced on the CPU
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_ROW_TRACER_HPP
#define SBRT_GL_GPU_ROW_TRACER_HPP

#include <optional>
#include <vector>

#include "gpu_tracer.hpp"

namespace sbrt_gl {

/// The pixels of `camera`'s image that the CPU traces where `tracer`'s
/// GPU draws the model: none (no overlays drawn with the model),
/// rectangles (those whose rays may meet a borehole), or every pixel
/// (none: a borehole's box reaches behind the camera).
std::optional<std::vector<sbrt::PixelRect>> cpu_pixels_of(const sbrt::Tracer &tracer,
                                                          const sbrt::Camera &camera);

/// \brief Rows of `camera`'s image from the GPU: hit records, or (with
/// shade_on_gpu) the shaded outputs of whole bands. Shading, the GPU draws
/// the model and its boreholes (or boreholes and curtains alone). Hit
/// records hold no normals of a borehole's surfaces: where the GPU writes
/// them for a scene with boreholes drawn with the model (or curtains:
/// shaded too), the pixels whose rays may meet one (the projections of
/// their boxes) are traced again by the exact CPU tracer, which draws
/// both: no other ray can meet a borehole, and elsewhere the two agree.
class GpuRowTracer : public sbrt::RowTracer {
public:
    GpuRowTracer(GpuTracer &gpu, const sbrt::Camera &camera, unsigned cpu_threads = 0);

    void trace_rows(int first, int count, sbrt::Hit *out) override;
    /// With `shading` the GPU shades too (and finds kernel normals where
    /// shades_kernel_normals says).
    void shade_on_gpu(const sbrt::Shading *shading) { shading_ = shading; }
    /// Kernel normals on the GPU: where it shades, the image fits, no
    /// borehole's pixels come from the CPU (their kernels read the GPU's
    /// depths) and, for a model read block by block, the image's hit
    /// records (traced when first asked: GpuTracer::prepare_kernel) met
    /// every block on the GPU: a ray sent back shows nothing to its
    /// neighbours' kernels.
    bool shades_kernel_normals() const override;
    /// Bands of a million pixels or more: enough rays to fill a GPU; of
    /// fewer where a paged model's atlas is crowded (crowded_band_rows).
    int preferred_band_rows(int cols) const override;
    /// What one mapped band holds (GpuTracer::max_band_rows).
    int max_band_rows(int cols, const sbrt::Outputs &outputs) const override;
    bool shade_rows(int first, int count, const sbrt::Outputs &outputs,
                    sbrt::Band &band) override;

    /// The pixels traced on the CPU: none (no overlays drawn with the
    /// model), rectangles, or every pixel (none: the camera is among the
    /// boreholes).
    /// Found when first asked: a frame the GPU shades with face normals
    /// never needs them.
    const std::optional<std::vector<sbrt::PixelRect>> &cpu_pixels() const;

private:
    /// Whether the CPU traces any pixel.
    bool any_cpu_pixels() const { return !cpu_pixels() || !cpu_pixels()->empty(); }
    /// Calls f(row, col) for each pixel of rows [first, first + count)
    /// the CPU traces, on the threads.
    template <typename PixelFunction>
    void for_cpu_pixels(int first, int count, const PixelFunction &f) const;

    GpuTracer &gpu_;
    const sbrt::Camera &camera_;
    unsigned threads_;
    const sbrt::Shading *shading_ = nullptr;
    /// whether this camera's hit records are on the GPU, and complete
    mutable std::optional<bool> kernel_prepared_;
    mutable bool cpu_rects_found_ = false;
    mutable std::optional<std::vector<sbrt::PixelRect>> cpu_rects_;
};

} // namespace sbrt_gl

#endif
