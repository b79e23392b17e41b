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
/// reaches. The boreholes' pass draws these tiles; the GPU lists them
/// itself (shaders/tile_cull.comp), and the tests hold its lists to this.
OverlayTiles overlay_tiles(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                           const Camera &camera, int first_row, int rows);

/// Whether some of `boxes` lies partly behind `camera` (the camera among
/// them): then overlay_tiles lists every tile, without box lists.
bool overlay_tiles_everywhere(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                              const Camera &camera);

/// Head of `buffer Tiles` (binding 12) of a band in the boreholes' pass
/// (SBRT_TILE_LIST), which the GPU's culling pass (shaders/tile_cull.comp,
/// a work group a box) fills: the band's tiles that a box's projection,
/// one pixel wider, reaches, as overlay_tiles lists them on the host.
/// After the head (words): the listed tiles (x | y << 16, in no order); a
/// count for each tile of the band (row by row) of the boxes that reach
/// it; `slots` box indices for each tile (a tile reached by more: its
/// pass tests every box).
struct GpuTileHead {
    /// the boreholes' pass's work groups (glDispatchComputeIndirect): x is
    /// the count of tiles listed, 0 until the culling pass counts them
    uint32_t groups[3] = {0, 1, 1};
    /// box indices a tile; 0: every tile listed by the host, no box lists
    /// (a box partly behind the camera)
    uint32_t slots = 0;
    uint32_t tile_cols = 0, tile_rows = 0, boxes = 0;
    uint32_t list_at = 0, counts_at = 0, slots_at = 0, words = 0, pad = 0;
    /// Camera::pixel_rows in the local frame, the band's first row at 0:
    /// xyz the coefficients of v = p - the camera, w the constant
    float pixel_rows[3][4] = {};
    /// the camera in the local frame as floats hi + lo (xyz): v is (p -
    /// hi) - lo, whose rounding grows with the distance to the camera,
    /// not with the distance to local 0
    float camera_hi[4] = {}, camera_lo[4] = {};
    /// a ray's t at local point p: dot(xyz, v) + w (ray_t_form), v as
    /// above; a box's least over its corners is the least t at which a ray
    /// enters it
    float ray_t[4] = {};
    /// where `buffer HitTs` (binding 13) holds the farthest t of each
    /// tile's model hits (the model pass writes them after the band's
    /// pixels' ts): a tile whose model hits all lie before a box's least t
    /// is not listed for that box
    uint32_t far_at = 0, pad_end[3] = {};
};
static_assert(sizeof(GpuTileHead) == 40 * 4, "40 words");

/// The head of the band of `rows` rows from `first_row` of `camera`'s
/// image, with `boxes` boxes and `slots` box indices a tile (0: every
/// tile listed, see gpu_every_tile_list).
GpuTileHead make_gpu_tile_head(const Tracer &tracer, const Camera &camera, int first_row,
                               int rows, uint32_t boxes, uint32_t slots);

/// The words of `head` (slots 0) listing every tile of its band.
std::vector<uint32_t> gpu_every_tile_list(GpuTileHead head);

/// `buffer Boxes` (binding 14) of the boreholes' pass and its culling:
/// each box as its low and high corner in `tracer`'s local frame (three
/// floats each), a thousandth of a local unit wider, rounded outwards.
std::vector<float> make_gpu_boxes(const Tracer &tracer,
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
