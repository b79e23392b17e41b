/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The overlays' storage buffers for the GPU
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_overlays.hpp"

#include <algorithm>
#include <cstring>
#include <tuple>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// Where `stack` goes in `logs`: its first index and count.
std::pair<uint32_t, uint32_t> append(std::vector<Interval> &logs,
                                     const std::vector<Interval> &stack)
{
    const size_t first = logs.size();
    logs.insert(logs.end(), stack.begin(), stack.end());
    if (logs.size() > GPU_PANEL)
        fail("the boreholes' logs hold more than ", GPU_PANEL, " intervals");
    return {uint32_t(first), uint32_t(stack.size())};
}

} // namespace

GpuOverlayMode gpu_overlay_mode(const Tracer &tracer)
{
    const Scene &scene = tracer.scene();
    // without the model, overlays that touch no cell leave nothing to draw
    // (not the model)
    if (!scene.draw_model)
        return GpuOverlayMode::alone;
    if (!tracer.has_overlays())
        return GpuOverlayMode::none;
    return scene.fence.empty() ? GpuOverlayMode::with_model : GpuOverlayMode::on_cpu;
}

std::vector<uint32_t> overlay_tiles(const std::optional<std::vector<PixelRect>> &rects,
                                    int first_row, int rows, int cols)
{
    const int side = 8;
    const int tile_cols = (cols + side - 1) / side, tile_rows = (rows + side - 1) / side;
    if (tile_cols > 0xffff || tile_rows > 0xffff)
        fail("overlay_tiles: ", tile_cols, " x ", tile_rows, " tiles, more than 65535 a side");
    std::vector<uint8_t> marked(size_t(tile_cols) * size_t(tile_rows), rects ? 0 : 1);
    if (rects)
        for (const PixelRect &r : *rects) {
            // rows [r[0], r[1]] and columns [r[2], r[3]] within the band
            const int r0 = std::max(r[0], first_row) - first_row;
            const int r1 = std::min(r[1], first_row + rows - 1) - first_row;
            const int c0 = std::max(r[2], 0), c1 = std::min(r[3], cols - 1);
            if (r0 > r1 || c0 > c1)
                continue;
            for (int ty = r0 / side; ty <= r1 / side; ++ty)
                std::fill_n(marked.begin() + ptrdiff_t(size_t(ty) * size_t(tile_cols) +
                                                       size_t(c0 / side)),
                            c1 / side - c0 / side + 1, uint8_t(1));
        }
    std::vector<uint32_t> tiles;
    for (int ty = 0; ty < tile_rows; ++ty)
        for (int tx = 0; tx < tile_cols; ++tx)
            if (marked[size_t(ty) * size_t(tile_cols) + size_t(tx)])
                tiles.push_back(uint32_t(tx) | uint32_t(ty) << 16);
    return tiles;
}

GpuOverlays make_gpu_overlays(const Tracer &tracer)
{
    const Scene &scene = tracer.scene();
    GpuOverlayHead head{};
    head.borehole_radius = float(scene.borehole_radius);
    head.curtain_length = float(scene.translucency.length);
    if (scene.split) {
        head.split[0] = float(scene.split->x);
        head.split[1] = float(scene.split->y);
    }
    head.map_unit[0] = float(tracer.frame().voxel_size().x);
    head.map_unit[1] = float(tracer.frame().voxel_size().y);
    std::vector<GpuOverlay> overlays;
    GpuOverlays out;
    auto local = [&](glm::dvec2 p) { return glm::dvec2(tracer.frame().to_local(glm::dvec3(p, 0))); };
    for (const Borehole &b : scene.boreholes) {
        const glm::dvec2 c = local({b.x, b.y});
        GpuOverlay o{{float(c.x), float(c.y), float(c.x), float(c.y)}, 0, 0, 0, 0};
        std::tie(o.log_first, o.log_count) = append(out.logs, b.stack);
        std::tie(o.model_first, o.model_count) = append(out.logs, b.model_stack);
        overlays.push_back(o);
    }
    for (const FencePanel &p : scene.fence) {
        const glm::dvec2 a = local(p.a), b = local(p.b);
        overlays.push_back({{float(a.x), float(a.y), float(b.x), float(b.y)}, GPU_PANEL, 0, 0, 0});
    }
    head.count[0] = uint32_t(overlays.size());
    out.words.resize((sizeof head + overlays.size() * sizeof(GpuOverlay)) / 4);
    std::memcpy(out.words.data(), &head, sizeof head);
    if (!overlays.empty())
        std::memcpy(out.words.data() + sizeof head / 4, overlays.data(),
                    overlays.size() * sizeof(GpuOverlay));
    if (out.logs.empty())
        out.logs.push_back({0, 0}); // a buffer is never empty
    if (gpu_overlay_mode(tracer) == GpuOverlayMode::with_model) {
        // the tracer's lists, a panel after the boreholes
        out.cells = tracer.overlay_cell_offsets();
        const uint32_t boreholes = uint32_t(scene.boreholes.size());
        for (uint32_t item : tracer.overlay_cell_items())
            out.cells.push_back(item & Tracer::OVERLAY_PANEL
                                    ? boreholes + (item & ~Tracer::OVERLAY_PANEL)
                                    : item);
    }
    return out;
}

} // namespace sbrt
