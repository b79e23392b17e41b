/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   C++ mirror of the overlays' storage buffers of
 *            shaders/common/overlays.glsl: boreholes (their logs) and
 *            fence curtains of a scene that draws only them, in the
 *            tracer's local frame
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GPU_OVERLAYS_HPP
#define SBRT_GPU_OVERLAYS_HPP

#include <cstdint>
#include <vector>

#include <array>

#include <glm/vec3.hpp>

#include "model/interval_array.hpp"
#include "scene/camera.hpp"
#include "tracing/cpu_tracing.hpp"
#include "tracing/tracer.hpp"

namespace sbrt {

/// Head of `buffer Overlays` (std430): three vec4/uvec4.
struct GpuOverlayHead {
    float borehole_radius;   ///< map units
    float curtain_length;    ///< Translucency::length: what a curtain absorbs
    float split[2];          ///< split cylinders' direction (map x, y; 0, 0: none)
    float map_unit[4];       ///< xy: map units per local unit (ew_res, ns_res)
    uint32_t count[4];       ///< x: overlays
};
static_assert(sizeof(GpuOverlayHead) == 48, "three std430 vec4");

/// One overlay (std430: vec4, uvec4): a fence panel from (x0, y0) to
/// (x1, y1), or a borehole's axis at (x0, y0) = (x1, y1); local x, y.
/// A borehole's log is logs[log_first, + log_count), its model stack
/// logs[model_first, + model_count); a panel has log_first = GPU_PANEL.
struct GpuOverlay {
    float ends[4];
    uint32_t log_first, log_count, model_first, model_count;
};
static_assert(sizeof(GpuOverlay) == 32, "std430 vec4 + uvec4");

constexpr uint32_t GPU_PANEL = 0xffffffffu;

/// How the GPU draws a tracer's boreholes and fence panels.
enum class GpuOverlayMode {
    none,       ///< there are none
    alone,      ///< the model is not drawn: every ray meets them directly
                ///< (SBRT_OVERLAYS)
    with_model, ///< boreholes in the cells the DDA crosses (SBRT_BOREHOLES;
                ///< shaded passes only)
    on_cpu      ///< curtains with the model: the CPU traces their pixels
};
GpuOverlayMode gpu_overlay_mode(const Tracer &tracer);
/// Whether the shading program draws them (alone or with the model).
inline bool shaded_on_gpu(GpuOverlayMode mode)
{
    return mode == GpuOverlayMode::alone || mode == GpuOverlayMode::with_model;
}

/// \brief The 8 x 8 pixel tiles (work groups) of a band whose pixels' rays
/// may meet an overlay's box, and the boxes each may meet.
struct OverlayTiles {
    std::vector<uint32_t> tiles;     ///< band-local x | y << 16, row by row
    std::vector<uint32_t> box_first; ///< per tile, then one past: its boxes
    std::vector<uint32_t> boxes;     ///< box indices
    /// A box lies partly behind the camera: every tile, no box lists.
    bool every_tile = false;
};

/// The tiles of rows [first_row, first_row + rows) of `camera`'s image
/// whose pixels' rays may meet one of `boxes` (Tracer::overlay_boxes):
/// those the convex hull of a box's projected corners, one pixel wider,
/// reaches (the work groups of the boreholes' pass, SBRT_TILE_LIST).
OverlayTiles overlay_tiles(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                           const Camera &camera, int first_row, int rows);

/// Whether some of `boxes` lies partly behind `camera` (the camera among
/// them): then overlay_tiles lists every tile, without box lists.
bool overlay_tiles_everywhere(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                              const Camera &camera);

/// `buffer Tiles` (binding 12, SBRT_TILE_LIST) of `tiles`: the count of
/// tiles, where the box lists' offsets, the box indices and the boxes
/// start (words); the tiles; each tile's first box, and one past; the box
/// indices; each box as its low and high corner in `tracer`'s local frame
/// (three floats each), a thousandth of a local unit wider.
std::vector<uint32_t> make_gpu_tile_list(const OverlayTiles &tiles, const Tracer &tracer,
                                         const std::vector<std::array<glm::dvec3, 2>> &boxes);

/// The overlays of the tracer's scene on the GPU: the Overlays buffer's
/// words (head, then the overlays), the logs (intervals, local tops) and,
/// with the model, `buffer CellOverlays`: each cell's first item (cells +
/// 1 words, row-major from the north), then the items, indices into the
/// overlays.
struct GpuOverlays {
    std::vector<uint32_t> words;
    std::vector<Interval> logs;
    std::vector<uint32_t> cells;
};

/// Every borehole and fence panel of `tracer`'s scene.
GpuOverlays make_gpu_overlays(const Tracer &tracer);

} // namespace sbrt

#endif
