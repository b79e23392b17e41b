/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Scene pruning before upload
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/scene_pruning.hpp"

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

Pruning prune_for_view(const Tracer &tracer, const Camera &camera)
{
    const Model &model = tracer.model();
    const Frame &f = model.frame();
    const MinMaxPyramid &pyramid = tracer.pyramid();
    const CoordinateFrame &frame = tracer.frame();
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
                if (size && pyramid.levels() && pyramid.node(0, col, y).empty())
                    left_out = &out.cut_away;
                else if (size) {
                    const double top = model.intervals()[model.stack_end(cell) - 1].top;
                    const glm::dvec3 low = frame.exaggerate(frame.from_local({col, y, 0}));
                    const glm::dvec3 high =
                        frame.exaggerate(frame.from_local({col + 1, y + 1, top}));
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

Pruning prune_for_view(const Model &model, double zexag, const Scene &scene,
                       const Camera &camera)
{
    return prune_for_view(Tracer(model, zexag, scene), camera);
}

} // namespace sbrt
