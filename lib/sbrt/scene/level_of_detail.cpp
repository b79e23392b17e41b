/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The coarse level of detail of a model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/level_of_detail.hpp"

#include <algorithm>
#include <vector>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// Cells of the coarse grid of `frame` at `factor`.
uint64_t coarse_cells(const Frame &frame, int factor)
{
    const uint64_t rows = (uint64_t(frame.rows) + factor - 1) / factor;
    const uint64_t cols = (uint64_t(frame.cols) + factor - 1) / factor;
    return rows * cols;
}

/// The fine row (or column) under the centre of coarse row `coarse` when
/// `fine` rows are shown as `coarse_count`: floor((coarse + 1/2) * fine /
/// coarse_count), in integers so that it is exact.
int fine_index(int coarse, int fine, int coarse_count)
{
    const int64_t index = (2 * int64_t(coarse) + 1) * fine / (2 * int64_t(coarse_count));
    return int(std::min<int64_t>(index, fine - 1));
}

} // namespace

int level_of_detail_factor(const Frame &frame)
{
    // Why these sizes: the viewer's reduced frame while the camera moves is
    // about 400 x 300 (120,000 pixels); the scene preparation and the
    // walk through the cells cost by the cells, so a level of at most
    // 500,000 cells (a coarse cell per few pixels of a view of the whole
    // model) draws such a frame at the cost of a small model, while each
    // pixel's footprint still covers about one coarse cell. A model of
    // fewer than 512 x 512 cells is drawn that fast already.
    if (frame.cells() < LOD_MIN_CELLS)
        return 1;
    int factor = 2;
    while (coarse_cells(frame, factor) > LOD_MAX_CELLS)
        factor *= 2;
    return factor;
}

Model coarsened(const Model &model, int factor)
{
    if (factor < 1)
        fail("coarsened: factor ", factor, " is not 1 or more");
    const Frame &fine = model.frame();
    Frame frame = fine; // the same extent and vertical frame
    frame.rows = int((int64_t(fine.rows) + factor - 1) / factor);
    frame.cols = int((int64_t(fine.cols) + factor - 1) / factor);

    // each coarse cell: the stack of the fine cell under its centre
    std::vector<int> fine_cols(size_t(frame.cols));
    for (int c = 0; c < frame.cols; ++c)
        fine_cols[size_t(c)] = fine_index(c, fine.cols, frame.cols);
    std::vector<uint32_t> offsets;
    offsets.reserve(size_t(frame.cells()) + 1);
    offsets.push_back(0);
    Intervals intervals;
    for (int r = 0; r < frame.rows; ++r) {
        const int fine_row = fine_index(r, fine.rows, frame.rows);
        for (int c = 0; c < frame.cols; ++c) {
            const StackRange stack = model.stack(model.cell_index(fine_row, fine_cols[size_t(c)]));
            for (uint64_t i = stack.begin; i < stack.end; ++i)
                intervals.push_back(model.intervals()[i]);
            if (intervals.size() > UINT32_MAX)
                fail("coarsened: more than ", uint64_t(UINT32_MAX), " intervals");
            offsets.push_back(uint32_t(intervals.size()));
        }
    }
    Model out(frame, model.materials(), offsets, IntervalArray(std::move(intervals)));
    out.set_vertical_datum(model.vertical_datum());
    return out;
}

} // namespace sbrt
