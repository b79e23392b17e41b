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

CoarseLevelBuilder::CoarseLevelBuilder(const Frame &fine, int factor) : fine_(fine), frame_(fine)
{
    if (factor < 1)
        fail("coarsened: factor ", factor, " is not 1 or more");
    // the same extent and vertical frame
    frame_.rows = int((int64_t(fine.rows) + factor - 1) / factor);
    frame_.cols = int((int64_t(fine.cols) + factor - 1) / factor);
    fine_cols_.resize(size_t(frame_.cols));
    for (int c = 0; c < frame_.cols; ++c)
        fine_cols_[size_t(c)] = fine_index(c, fine.cols, frame_.cols);
    offsets_.reserve(size_t(frame_.cells()) + 1);
    offsets_.push_back(0);
}

void CoarseLevelBuilder::add_rows(const Model &band, int first_row)
{
    const int rows = band.frame().rows;
    if (band.frame().cols != fine_.cols || first_row < 0 || rows > fine_.rows - first_row)
        fail("coarsened: a band of ", rows, " x ", band.frame().cols, " cells at row ",
             first_row, " is not within a model of ", fine_.rows, " x ", fine_.cols);
    // each coarse cell: the stack of the fine cell under its centre
    for (; next_row_ < frame_.rows; ++next_row_) {
        const int fine_row = fine_index(next_row_, fine_.rows, frame_.rows);
        if (fine_row < first_row)
            fail("coarsened: fine row ", fine_row, " was not given");
        if (fine_row >= first_row + rows)
            return;
        for (int c = 0; c < frame_.cols; ++c) {
            const StackRange stack =
                band.stack(band.cell_index(fine_row - first_row, fine_cols_[size_t(c)]));
            for (uint64_t i = stack.begin; i < stack.end; ++i)
                intervals_.push_back(band.intervals()[i]);
            if (intervals_.size() > UINT32_MAX)
                fail("coarsened: more than ", uint64_t(UINT32_MAX), " intervals");
            offsets_.push_back(uint32_t(intervals_.size()));
        }
    }
}

Model CoarseLevelBuilder::finish(std::vector<Material> materials)
{
    if (next_row_ != frame_.rows)
        fail("coarsened: ", next_row_, " of ", frame_.rows, " coarse rows were given");
    return Model(frame_, std::move(materials), offsets_, IntervalArray(std::move(intervals_)));
}

Model coarsened(const Model &model, int factor)
{
    CoarseLevelBuilder builder(model.frame(), factor);
    builder.add_rows(model, 0);
    Model out = builder.finish(model.materials());
    out.set_vertical_datum(model.vertical_datum());
    return out;
}

} // namespace sbrt
