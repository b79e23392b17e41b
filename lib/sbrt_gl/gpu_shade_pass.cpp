/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The shading pass: shaded bands of rows in mapped memory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_shade_pass.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include "gpu_internal.hpp"
#include "gpu/gpu_overlays.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt_gl {

GpuShadePass::GpuShadePass(const PassContext &passes, bool staged)
    : passes_(passes), bands_(passes.gl, passes.max_block_bytes, staged),
      host_shader_(passes.tracer.model())
{
}

GpuShadePass::Plan GpuShadePass::plan(const sbrt::Camera &camera,
                                      const sbrt::Shading &shading) const
{
    Plan plan;
    plan.model_program = &passes_.shading_program(shading, Pass::shade);
    // boreholes with the model: the model alone everywhere, then the model
    // and the boreholes again over the tiles where a ray may meet one (no
    // other ray pays for them)
    if (sbrt::gpu_overlay_mode(passes_.tracer) == sbrt::GpuOverlayMode::with_model) {
        plan.borehole_program = &passes_.shading_program(shading, Pass::shade_boreholes);
        // the camera among the boxes: every tile in the boreholes' pass,
        // and no model pass (no box lists to test its hits against)
        plan.every_tile = sbrt::overlay_tiles_everywhere(passes_.tracer.overlay_boxes(), camera);
    }
    return plan;
}

sbrt::GpuBandLayout GpuShadePass::band_layout(const sbrt::Camera &camera, int count,
                                              const sbrt::Outputs &outputs,
                                              sbrt::GpuShade &shade)
{
    const std::optional<sbrt::GpuBandLayout> layout =
        bands_.layout(count, camera.cols(), outputs);
    if (!layout)
        sbrt::fail("a band of ", count, " rows of ", camera.cols(),
                   " pixels does not fit this GPU's largest storage buffer (",
                   passes_.max_block_bytes, " bytes): fewer rows a band");
    sbrt::set_band_planes(shade, *layout);
    return *layout;
}

void GpuShadePass::dispatch_model(const sbrt::Camera &camera, Plan &plan, int first, int count)
{
    passes_.upload_view(plan.view, first, count);
    if (plan.every_tile)
        return;
    ++passes_.stats.model_pass_bands;
    // the model alone: skipping as if there were no boreholes
    passes_.model.bind_pyramid(plan.borehole_program != nullptr);
    plan.model_program->use();
    passes_.dispatch(Pass::shade, camera.cols(), count);
    passes_.model.bind_pyramid();
}

void GpuShadePass::shade(const sbrt::Camera &camera, int first_row, int row_count,
                         const sbrt::Shading &shading, const sbrt::GpuBandLayout &layout,
                         sbrt::Band &band, unsigned cpu_threads,
                         const std::function<void(int, int, int)> &dispatch, bool reads_model)
{
    bands_.reset_gpu_ms();
    uint8_t *host = bands_.band(first_row, row_count, camera.rows(), dispatch);
    // a paged model: the band again once the blocks its rays missed are up
    // (they are sent back as rays over the budget)
    const auto sent_back = [&] {
        uint32_t over = 0;
        std::memcpy(&over, host + layout.over_budget_at * 4, 4);
        return over;
    };
    PassContext::BandPaging paging = passes_.begin_band();
    while (reads_model && passes_.model.pages() && sent_back() > 0 &&
           passes_.band_again(paging))
        host = bands_.redo(dispatch);
    passes_.stats.trace_ms += bands_.gpu_ms();
    ++passes_.stats.bands;
    view_band(host, first_row, row_count, layout, band);
    shade_over_budget(camera, shading, host, layout, band, cpu_threads);
}

void GpuShadePass::view_band(uint8_t *host, int first_row, int row_count,
                             const sbrt::GpuBandLayout &layout, sbrt::Band &band)
{
    // the band views the mapped memory as the GPU wrote it
    const size_t cols = size_t(layout.cols);
    uint32_t *words = reinterpret_cast<uint32_t *>(host);
    band.first_row = first_row;
    band.rows = row_count;
    band.cols = layout.cols;
    band.rgb = sbrt::BandPlane<uint8_t>(host, layout.rgb_stride_words * 4);
    band.material = layout.material_at
                        ? sbrt::BandPlane<int32_t>(
                              reinterpret_cast<int32_t *>(words + layout.material_at), cols)
                        : sbrt::BandPlane<int32_t>();
    const auto doubles = [&](size_t at) {
        return at ? sbrt::BandPlane<double>(reinterpret_cast<double *>(words + at), cols)
                  : sbrt::BandPlane<double>();
    };
    band.elevation = doubles(layout.elevation_at);
    band.depth = doubles(layout.depth_at);
    band.value = sbrt::BandPlane<double>();
    passes_.stats.host_bytes += band.pixels() * band.bytes_per_pixel() + 4;
}

void GpuShadePass::shade_over_budget(const sbrt::Camera &camera, const sbrt::Shading &shading,
                                     const uint8_t *host, const sbrt::GpuBandLayout &layout,
                                     sbrt::Band &band, unsigned cpu_threads)
{
    // the count of rays the GPU sent back, then their pixels
    const uint32_t *words = reinterpret_cast<const uint32_t *>(host);
    const uint32_t over = words[layout.over_budget_at];
    if (over == 0)
        return;
    if (over > band.pixels())
        sbrt::fail("the GPU listed ", over, " rays over its loop budget in a band of ",
                   band.pixels(), " pixels");
    const auto start = Clock::now();
    const size_t cols = size_t(layout.cols);
    const uint32_t *pixels = words + layout.over_budget_at + 1;
    const sbrt::PixelShader &shader = host_shader(shading);
    const sbrt::Tracer &tracer = passes_.tracer;
    // 256 rays a thread: a ray traced alone takes microseconds, starting a
    // thread tens (the few dozen a property view sends back: one thread;
    // 16 host threads made a frame slower than one: docs/performance.md)
    constexpr uint32_t CHUNK = 256;
    const int chunks = int((over + CHUNK - 1) / CHUNK);
    sbrt::for_each_row(0, chunks, cpu_threads, [&](int chunk) {
        const uint32_t end = std::min<uint32_t>(over, uint32_t(chunk + 1) * CHUNK);
        for (uint32_t k = uint32_t(chunk) * CHUNK; k < end; ++k) {
            const int row = band.first_row + int(pixels[k] / cols), col = int(pixels[k] % cols);
            const sbrt::Hit hit = tracer.trace(camera.ray(row, col));
            sbrt::shade_into_band(tracer, shader, camera, hit, row, col, band);
        }
    });
    passes_.stats.over_budget += over;
    passes_.stats.host_bytes += size_t(over) * (4 + band.bytes_per_pixel());
    passes_.stats.readback_ms += ms_since(start);
}

} // namespace sbrt_gl
