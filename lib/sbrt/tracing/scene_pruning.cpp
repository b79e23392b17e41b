/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Scene pruning before upload
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/scene_pruning.hpp"

#include <glm/geometric.hpp>

#include "scene/overlay_geometry.hpp"

namespace sbrt {

bool outside_view(const Camera &camera, glm::dvec3 low, glm::dvec3 high)
{
    // pixel centres lie inside (-1, 1) x (-1, 1) in normalised device
    // coordinates; count the corners beyond each edge
    int behind = 0, left = 0, right = 0, below = 0, above = 0;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p(k & 1 ? high.x : low.x, k & 2 ? high.y : low.y,
                           k & 4 ? high.z : low.z);
        double x, y;
        if (!camera.project(p, x, y)) {
            ++behind;
            continue;
        }
        left += x < -1;
        right += x > 1;
        below += y < -1;
        above += y > 1;
    }
    // a corner behind the camera projects nowhere: only all behind counts
    return behind == 8 ||
           (behind == 0 && (left == 8 || right == 8 || below == 8 || above == 8));
}

namespace {

/// Which non-empty stacks are cut away: with the tracer's pyramid, its
/// level 0 (empty where the tracer will never draw the column).
template <typename CutAway>
Pruning prune(const Model &model, const CoordinateFrame &frame, const Camera &camera,
              const CutAway &cut_away)
{
    const Frame &f = model.frame();
    Pruning out;
    std::vector<uint32_t> sizes(f.cells(), 0);
    IntervalArray kept = model.intervals().visit([&](const auto *records) {
        using Record = RecordOf<decltype(records)>;
        std::vector<Record, UnfilledAllocator<Record>> intervals;
        intervals.reserve(model.intervals().size());
        for (int row = 0; row < f.rows; ++row)
            for (int col = 0; col < f.cols; ++col) {
                const uint64_t cell = model.cell_index(row, col);
                const uint32_t size = model.stack_size(cell);
                const int y = f.rows - 1 - row;
                Pruned *left_out = nullptr;
                if (size && cut_away(cell, col, y))
                    left_out = &out.cut_away;
                else if (size) {
                    const double top = model.intervals()[model.stack_end(cell) - 1].top;
                    const glm::dvec3 low =
                        frame.exaggerated_from_map(frame.map_from_local({col, y, 0}));
                    const glm::dvec3 high =
                        frame.exaggerated_from_map(frame.map_from_local({col + 1, y + 1, top}));
                    if (outside_view(camera, low, high))
                        left_out = &out.outside_view;
                }
                if (left_out) {
                    left_out->cells += 1;
                    left_out->intervals += size;
                    left_out->bytes += size * sizeof(Record);
                }
                else {
                    const StackRange stack = model.stack(cell);
                    intervals.insert(intervals.end(), records + stack.begin, records + stack.end);
                    sizes[cell] = size;
                }
            }
        return IntervalArray(std::move(intervals));
    });
    out.model = Model(f, model.materials(), StackIndex::from_sizes(sizes.data(), f.cells()),
                      std::move(kept));
    return out;
}

/// Cells (row-major, row 0 north) a borehole or fence panel of `scene`
/// touches: the tracer draws them whatever the planes cut.
std::vector<bool> overlay_cells(const Frame &f, const Scene &scene)
{
    std::vector<bool> touched(scene.boreholes.empty() && scene.fence.empty() ? 0 : f.cells());
    for (const Borehole &b : scene.boreholes)
        for (uint64_t c : cells_near_segment(f, {b.x, b.y}, {b.x, b.y}, scene.borehole_radius))
            touched[c] = true;
    for (const FencePanel &panel : scene.fence)
        for (uint64_t c : cells_near_segment(f, panel.a, panel.b, 0))
            touched[c] = true;
    return touched;
}

/// A clip plane in the local frame: f(l) = n . l + c, removed where f > 0
/// (Tracer::LocalPlane without its shading normal).
struct LocalCut {
    glm::dvec3 n;
    double c;
};

std::vector<LocalCut> local_cuts(const CoordinateFrame &frame,
                                 const std::vector<ClipPlane> &planes)
{
    const Frame &f = frame.grid();
    const glm::dvec3 base(f.west, f.south, f.bottom);
    std::vector<LocalCut> cuts;
    for (const ClipPlane &plane : planes) {
        const glm::dvec3 n(plane.normal.x, plane.normal.y, plane.normal.z / frame.zexag());
        const double length = glm::length(n);
        cuts.push_back({n / frame.scale() / length,
                        glm::dot(n, base - frame.exaggerated_from_map(plane.point)) / length});
    }
    return cuts;
}

/// The cell's drawn z-range as the pyramid's level 0 holds it: from the
/// top of its leading EMPTY intervals (0 without) to its top; empty where
/// it holds no material.
template <typename Record>
ZRange solid_range(const Record *first, const Record *last)
{
    const Record *solid = first;
    while (solid != last && solid->material == EMPTY)
        ++solid;
    if (solid == last)
        return {};
    return {solid == first ? 0.0f : float((solid - 1)->top), float((last - 1)->top)};
}

/// Whether a plane leaves the whole column x, y over `range` on its
/// removed side (the test Tracer::build_pyramid makes).
bool removed_by_a_plane(const std::vector<LocalCut> &cuts, int x, int y, ZRange range)
{
    for (const LocalCut &cut : cuts) {
        bool removed = true;
        for (int k = 0; k < 8 && removed; ++k) {
            const glm::dvec3 l(x + (k & 1), y + ((k >> 1) & 1), k & 4 ? range.high : range.low);
            removed = glm::dot(cut.n, l) + cut.c > 0;
        }
        if (removed)
            return true;
    }
    return false;
}

} // namespace

Pruning prune_for_view(const Tracer &tracer, const Camera &camera)
{
    const MinMaxPyramid &pyramid = tracer.pyramid();
    return prune(tracer.model(), tracer.frame(), camera, [&](uint64_t, int x, int y) {
        return pyramid.levels() && pyramid.node(0, x, y).empty();
    });
}

Pruning prune_for_view(const Model &model, double zexag, const Scene &scene,
                       const Camera &camera)
{
    // only level 0 of the tracer's pyramid matters: no tracer is built
    // (the renderer builds the one of the pruned model)
    const CoordinateFrame frame = CoordinateFrame::of(model, zexag);
    const bool skipping = scene.skip_empty_space && scene.draw_model;
    const std::vector<bool> overlays = skipping ? overlay_cells(model.frame(), scene)
                                                : std::vector<bool>();
    const std::vector<LocalCut> cuts = local_cuts(frame, scene.planes);
    return model.intervals().visit([&](const auto *records) {
        return prune(model, frame, camera, [&](uint64_t cell, int x, int y) {
            if (!skipping || (!overlays.empty() && overlays[cell]))
                return false;
            const StackRange stack = model.stack(cell);
            const ZRange range = solid_range(records + stack.begin, records + stack.end);
            return range.empty() || removed_by_a_plane(cuts, x, y, range);
        });
    });
}

} // namespace sbrt
