/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The shading pass (shaders/shade.comp): rows traced and shaded
 *            on the GPU into mapped bands (MappedBands) that the host
 *            views, a paged model's band dispatched again as its blocks
 *            come up, the rays over the loop budget traced and shaded on
 *            the host; the kernel normals' shading lands there too
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_SHADE_PASS_HPP
#define SBRT_GL_GPU_SHADE_PASS_HPP

#include <chrono>
#include <functional>

#include "gl_objects.hpp"
#include "gpu_pass_context.hpp"
#include "mapped_bands.hpp"
#include "gpu/gpu_layout.hpp"
#include "scene/camera.hpp"
#include "shading/shading.hpp"
#include "output/band.hpp"

namespace sbrt_gl {

/// \brief The shading pass: the mapped bands the shaded rows land in and
/// the host's shader of the rays sent back. Holds a reference to the
/// tracer's PassContext; the context must be current.
class GpuShadePass {
public:
    /// `staged`: bands written into GPU memory and copied to the host by
    /// the GPU (MappedBands).
    GpuShadePass(const PassContext &passes, bool staged);

    /// What a frame's shading settles: the view block (each band's rows
    /// set as it is dispatched), the model pass's program, and with
    /// boreholes drawn with the model their pass's and whether every tile
    /// goes through it (the camera among their boxes: no model pass).
    struct Plan {
        sbrt::GpuView view{};
        GlComputeProgram *model_program = nullptr;
        GlComputeProgram *borehole_program = nullptr; ///< none: no boreholes pass
        bool every_tile = false;
    };
    /// The programs of `shading`'s frame of `camera` (Plan::view unset).
    Plan plan(const sbrt::Camera &camera, const sbrt::Shading &shading) const;
    /// The frame's band layout for `count` rows of `outputs` into `shade`.
    sbrt::GpuBandLayout band_layout(const sbrt::Camera &camera, int count,
                                    const sbrt::Outputs &outputs, sbrt::GpuShade &shade);
    /// A scratch buffer of `bytes` for each slot (binding 13; none: 0).
    void set_scratch(size_t bytes) { bands_.set_scratch(bytes, 13); }
    /// Queues the model pass of rows [first, first + count) of `plan`
    /// (none where every tile goes through the boreholes' pass), the view
    /// block set to those rows.
    void dispatch_model(const sbrt::Camera &camera, Plan &plan, int first, int count);
    /// Rows [first, first + count) shaded by the bound program into a
    /// mapped band that `band` views: `dispatch(first, count, slot)` queues
    /// one band's dispatch into MappedBands' slot `slot`; where the program
    /// `reads_model` (paged), again once the blocks its rays missed are up;
    /// the rays over the loop budget traced and shaded on the host.
    void shade(const sbrt::Camera &camera, int first, int count, const sbrt::Shading &shading,
               const sbrt::GpuBandLayout &layout, sbrt::Band &band, unsigned cpu_threads,
               const std::function<void(int, int, int)> &dispatch, bool reads_model = true);

    /// A new frame: bands dispatched ahead for the last one are dropped.
    void begin_frame() { bands_.begin_frame(); }
    /// The slot of the band shaded last.
    int last_slot() const { return bands_.last_slot(); }
    /// When the GPU was found done with the last band shaded.
    std::chrono::steady_clock::time_point last_done() const { return bands_.last_done(); }
    bool staged() const { return bands_.staged(); }
    /// The host's shader of `shading` (kept while the shading stays).
    const sbrt::PixelShader &host_shader(const sbrt::Shading &shading)
    {
        return host_shader_.of(shading);
    }

private:
    /// The band of `host` memory as the GPU wrote it, viewed by `band`.
    void view_band(uint8_t *host, int first, int count, const sbrt::GpuBandLayout &layout,
                   sbrt::Band &band);
    /// The band's rays over the loop budget traced and shaded here (each
    /// pixel listed once: the boreholes' pass leaves the model pass's
    /// alone).
    void shade_over_budget(const sbrt::Camera &camera, const sbrt::Shading &shading,
                           const uint8_t *host, const sbrt::GpuBandLayout &layout,
                           sbrt::Band &band, unsigned cpu_threads);

    const PassContext &passes_;
    MappedBands bands_; ///< where shaded bands land
    /// the host's shader of the pixels it traces, kept while the shading
    /// stays as it was
    sbrt::KeptPixelShader host_shader_;
};

} // namespace sbrt_gl

#endif
