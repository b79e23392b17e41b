/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The overlays' storage buffers for the GPU
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_overlays.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "gpu/gpu_layout.hpp"
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

namespace {

using Point = glm::dvec2;

double cross(const Point &o, const Point &a, const Point &b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
std::vector<Point> convex_hull(std::vector<Point> points)
{
    std::sort(points.begin(), points.end(),
              [](const Point &a, const Point &b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (points.size() < 3)
        return points;
    std::vector<Point> hull(2 * points.size());
    size_t k = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    for (size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0)
            --k;
        hull[k++] = points[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

/// The x-extent of the convex polygon `hull` (at least 3 points) within
/// the horizontal slab y0 <= y <= y1: false where the slab misses it. Its
/// edges clipped to the slab; a rectangle spanning the slab meets the
/// polygon exactly where it meets that extent.
bool slab_extent(const std::vector<Point> &hull, double y0, double y1, double &x0, double &x1)
{
    x0 = INFINITY;
    x1 = -INFINITY;
    for (size_t i = 0; i < hull.size(); ++i) {
        Point a = hull[i], b = hull[(i + 1) % hull.size()];
        if (a.y > b.y)
            std::swap(a, b);
        if (b.y < y0 || a.y > y1)
            continue;
        // the edge from where it enters the slab to where it leaves
        const auto at = [&](double y) {
            return b.y == a.y ? a.x : a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y));
        };
        const double xa = a.y >= y0 ? a.x : at(y0), xb = b.y <= y1 ? b.x : at(y1);
        x0 = std::min({x0, xa, xb});
        x1 = std::max({x1, xa, xb});
    }
    return x0 <= x1;
}

} // namespace

bool overlay_tiles_everywhere(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                              const Camera &camera)
{
    for (const auto &box : boxes) {
        int behind = 0;
        projected_corners(box, camera, behind);
        if (behind > 0 && behind < 8)
            return true;
    }
    return false;
}

OverlayTiles overlay_tiles(const std::vector<std::array<glm::dvec3, 2>> &boxes,
                           const Camera &camera, int first_row, int rows)
{
    const int side = 8, cols = camera.cols();
    const int tile_cols = (cols + side - 1) / side, tile_rows = (rows + side - 1) / side;
    if (tile_cols > 0xffff || tile_rows > 0xffff)
        fail("overlay_tiles: ", tile_cols, " x ", tile_rows, " tiles, more than 65535 a side");
    OverlayTiles out;
    if (overlay_tiles_everywhere(boxes, camera)) {
        // the camera is among them: any pixel's ray may meet one
        out.every_tile = true;
        for (int ty = 0; ty < tile_rows; ++ty)
            for (int tx = 0; tx < tile_cols; ++tx) {
                out.tiles.push_back(uint32_t(tx) | uint32_t(ty) << 16);
                out.box_first.push_back(0);
            }
        out.box_first.push_back(0);
        return out;
    }
    // (tile, box) for each tile a box reaches, box by box
    std::vector<std::pair<uint32_t, uint32_t>> reached;
    for (size_t b = 0; b < boxes.size(); ++b) {
        const auto &box = boxes[b];
        // the corners in pixel coordinates of the band (pixel centres whole)
        int behind = 0;
        std::vector<Point> corners = projected_corners(box, camera, behind);
        for (Point &p : corners)
            p = Point((p.x + 1) / 2 * cols - 0.5, (1 - p.y) / 2 * camera.rows() - 0.5 - first_row);
        if (behind > 0)
            continue; // wholly behind a perspective camera: no ray goes there
        const std::vector<Point> hull = convex_hull(corners);
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (const Point &p : hull) {
            x0 = std::min(x0, p.x);
            x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y);
            y1 = std::max(y1, p.y);
        }
        // the tile rows of its bounds (one pixel of margin), clamped before the
        // conversion to int (a box far outside projects far outside any int)
        const auto tile = [&](double v, int tiles) {
            return int(std::clamp(std::floor(v / side), -1.0, double(tiles)));
        };
        const int ty0 = std::max(0, tile(y0 - 1, tile_rows)),
                  ty1 = std::min(tile_rows - 1, tile(y1 + 1, tile_rows));
        for (int ty = ty0; ty <= ty1; ++ty) {
            // the row's pixel centres, one pixel wider: where the hull lies
            // across them (a hull of fewer than 3 points: its bounds)
            double row_x0 = x0, row_x1 = x1;
            if (hull.size() >= 3 &&
                !slab_extent(hull, ty * side - 1.0, ty * side + side, row_x0, row_x1))
                continue;
            // tile tx's centres, one pixel wider: [8 tx - 1, 8 tx + 8]
            const int tx0 = int(std::clamp(std::ceil((row_x0 - side) / side), 0.0,
                                           double(tile_cols))),
                      tx1 = int(std::clamp(std::floor((row_x1 + 1) / side), -1.0,
                                           double(tile_cols - 1)));
            for (int tx = tx0; tx <= tx1; ++tx)
                reached.emplace_back(uint32_t(ty) * uint32_t(tile_cols) + uint32_t(tx),
                                     uint32_t(b));
        }
    }
    // grouped by tile, row by row, each tile's boxes in their order (a
    // counting sort on the tile)
    std::vector<uint32_t> first(size_t(tile_cols) * size_t(tile_rows) + 1, 0);
    for (const auto &[at, box] : reached)
        ++first[at + 1];
    for (size_t t = 0; t + 1 < first.size(); ++t) {
        if (first[t + 1] != 0) {
            out.tiles.push_back(uint32_t(t % size_t(tile_cols)) |
                                uint32_t(t / size_t(tile_cols)) << 16);
            out.box_first.push_back(first[t]);
        }
        first[t + 1] += first[t];
    }
    out.boxes.resize(reached.size());
    for (const auto &[at, box] : reached)
        out.boxes[first[at]++] = box;
    out.box_first.push_back(uint32_t(out.boxes.size()));
    return out;
}

GpuTileHead make_gpu_tile_head(const Tracer &tracer, const Camera &camera, int first_row,
                               int rows, uint32_t boxes, uint32_t slots)
{
    GpuTileHead head;
    head.slots = slots;
    head.tile_cols = uint32_t((camera.cols() + 7) / 8);
    head.tile_rows = uint32_t((rows + 7) / 8);
    if (head.tile_cols > 0xffff || head.tile_rows > 0xffff)
        fail("make_gpu_tile_head: ", head.tile_cols, " x ", head.tile_rows,
             " tiles, more than 65535 a side");
    head.boxes = boxes;
    const uint64_t tiles = uint64_t(head.tile_cols) * head.tile_rows;
    const uint64_t words = sizeof head / 4 + 2 * tiles + tiles * slots;
    if (words > UINT32_MAX)
        fail("make_gpu_tile_head: ", words, " words, beyond 32-bit indices");
    head.list_at = uint32_t(sizeof head / 4);
    head.counts_at = uint32_t(head.list_at + tiles);
    head.slots_at = uint32_t(head.counts_at + tiles);
    head.words = uint32_t(words);
    // the forms of a map point's offset from the camera, then of a local
    // one's (map offset = local offset / scale), the band's first row at 0
    const CoordinateFrame &frame = tracer.frame();
    const glm::dvec3 scale = frame.scale(), eye = frame.local_from_exaggerated(camera.origin());
    const std::array<glm::dvec4, 3> map = camera.pixel_rows();
    for (int k = 0; k < 3; ++k) {
        glm::dvec4 form = map[size_t(k)];
        if (k == 1)
            form -= double(first_row) * map[2];
        const glm::dvec4 local(glm::dvec3(form) / scale, form.w);
        for (int a = 0; a < 4; ++a)
            head.pixel_rows[k][a] = float(local[a]);
    }
    for (int a = 0; a < 3; ++a) {
        head.camera_hi[a] = float(eye[a]);
        head.camera_lo[a] = float(eye[a] - double(head.camera_hi[a]));
    }
    const glm::dvec4 t_form = ray_t_form(tracer, camera, eye);
    for (int a = 0; a < 4; ++a)
        head.ray_t[a] = float(t_form[a]);
    head.far_at = uint32_t(uint64_t(rows) * uint64_t(camera.cols()));
    return head;
}

std::vector<uint32_t> gpu_every_tile_list(GpuTileHead head)
{
    head.slots = 0;
    head.groups[0] = head.tile_cols * head.tile_rows;
    std::vector<uint32_t> words(sizeof head / 4);
    std::memcpy(words.data(), &head, sizeof head);
    for (uint32_t ty = 0; ty < head.tile_rows; ++ty)
        for (uint32_t tx = 0; tx < head.tile_cols; ++tx)
            words.push_back(tx | ty << 16);
    return words;
}

std::vector<float> make_gpu_boxes(const Tracer &tracer,
                                  const std::vector<std::array<glm::dvec3, 2>> &boxes)
{
    std::vector<float> out;
    const double pad = 1e-3;
    for (const auto &box : boxes) {
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 local = tracer.frame().local_from_exaggerated(
                glm::dvec3(box[k & 1].x, box[(k >> 1) & 1].y, box[(k >> 2) & 1].z));
            lo = glm::min(lo, local);
            hi = glm::max(hi, local);
        }
        // floats rounded outwards: the box never narrows
        for (const auto &[corner, outwards] : {std::pair{lo - pad, -INFINITY},
                                               std::pair{hi + pad, INFINITY}})
            for (int a = 0; a < 3; ++a) {
                float f = float(corner[a]);
                if (outwards < 0 ? double(f) > corner[a] : double(f) < corner[a])
                    f = std::nextafter(f, float(outwards));
                out.push_back(f);
            }
    }
    if (out.empty())
        out.push_back(0); // a buffer is never empty
    return out;
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
    auto local = [&](glm::dvec2 p) {
        return glm::dvec2(tracer.frame().local_from_exaggerated(glm::dvec3(p, 0)));
    };
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
