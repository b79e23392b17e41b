/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Min-max pyramid over the cells
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/minmax_pyramid.hpp"

#include <algorithm>

#include "util/parallel.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

std::vector<ZRange> MinMaxPyramid::block_ranges(const Model &model, int b,
                                                const std::vector<uint8_t> &hidden)
{
    const StackPages &pages = *model.pages();
    std::vector<ZRange> ranges;
    const StackBlock cells = pages.block_cells(b);
    ranges.reserve(size_t(cells.rows) * size_t(cells.cols));
    // a block that holds no hidden stratum (its summary's classes) keeps
    // its columns' stored ranges; only the others are decoded
    if (pages.has_column_ranges() && (hidden.empty() || !pages.block_may_hold(b, hidden))) {
        for (int row = cells.first_row; row < cells.first_row + cells.rows; ++row)
            for (int col = cells.first_col; col < cells.first_col + cells.cols; ++col)
                ranges.push_back(pages.column_ranges()[model.cell_index(row, col)]);
        return ranges;
    }
    const auto drawn = [&](const auto &r) {
        return r.material != EMPTY && (hidden.empty() || !hidden[r.material]);
    };
    const std::shared_ptr<const StackBlock> block = pages.block(b);
    block->intervals.visit([&](const auto *records) {
        for (int row = block->first_row; row < block->first_row + block->rows; ++row)
            for (int col = block->first_col; col < block->first_col + block->cols; ++col) {
                const StackRange s = block->range(row, col);
                ranges.push_back(drawn_range(records + s.begin, records + s.end, drawn));
            }
    });
    return ranges;
}

void MinMaxPyramid::for_each_block(const Model &model, const std::function<void(int)> &visit)
{
    for_each_row(model.pages()->block_count(), 0, visit);
}

std::vector<ZRange> MinMaxPyramid::cell_ranges(const Model &model,
                                               const std::vector<uint8_t> &hidden)
{
    const Frame &f = model.frame();
    std::vector<ZRange> cells(f.cells());
    const auto drawn = [&](const auto &r) {
        return r.material != EMPTY && (hidden.empty() || !hidden[r.material]);
    };
    // row 0 of the model is the north edge, y = 0 of the pyramid the south
    const auto at = [&](int row, int col) -> ZRange & {
        return cells[size_t(f.rows - 1 - row) * f.cols + col];
    };
    if (const StackPages *pages = model.pages()) {
        for_each_block(model, [&](int b) {
            const std::vector<ZRange> ranges = block_ranges(model, b, hidden);
            const StackBlock block = pages->block_cells(b);
            size_t k = 0;
            for (int row = block.first_row; row < block.first_row + block.rows; ++row)
                for (int col = block.first_col; col < block.first_col + block.cols; ++col)
                    at(row, col) = ranges[k++];
        });
        return cells;
    }
    model.intervals().visit([&](const auto *records) {
        for (int row = 0; row < f.rows; ++row)
            for (int col = 0; col < f.cols; ++col) {
                const StackRange s = model.stack(model.cell_index(row, col));
                at(row, col) = drawn_range(records + s.begin, records + s.end, drawn);
            }
    });
    return cells;
}

void MinMaxPyramid::build(int cols, int rows, std::vector<ZRange> cells)
{
    levels_.push_back(std::move(cells));
    dims_.push_back({cols, rows});
    build_above();
}

void MinMaxPyramid::build_over_shared(int cols, int rows, std::vector<ZRange> level_1)
{
    levels_.emplace_back(); // the shared base
    dims_.push_back({cols, rows});
    if (cols > 1 || rows > 1) {
        levels_.push_back(std::move(level_1));
        dims_.push_back({(cols + 1) / 2, (rows + 1) / 2});
        level_0_wider_ = true;
    }
    build_above();
}

void MinMaxPyramid::build_above()
{
    int cols = dims_.back().first, rows = dims_.back().second;
    while (cols > 1 || rows > 1) {
        const int level = int(dims_.size()) - 1;
        const int up_cols = (cols + 1) / 2, up_rows = (rows + 1) / 2;
        std::vector<ZRange> up = vector_on_huge_pages<ZRange>(size_t(up_cols) * up_rows);
        // each node of the level above from the two rows below it, the
        // rows of nodes on all cores (a national model's level 0 is 7.4
        // million cells, walked on every opening)
        const unsigned threads = size_t(cols) * size_t(rows) < (size_t(1) << 16) ? 1 : 0;
        for_each_row(up_rows, threads, [&](int up_y) {
            ZRange *out = up.data() + size_t(up_y) * up_cols;
            for (int y = 2 * up_y; y < std::min(rows, 2 * up_y + 2); ++y)
                visit_row(level, y, [&](const auto *in) {
                    for (int x = 0; x < cols; ++x)
                        widen(out[x / 2], widened(in[x]));
                });
        });
        levels_.push_back(std::move(up));
        dims_.push_back({up_cols, up_rows});
        cols = up_cols;
        rows = up_rows;
    }
}

uint64_t MinMaxPyramid::empty_cells() const
{
    if (dims_.empty())
        return 0;
    uint64_t n = 0;
    for (int y = 0; y < rows(0); ++y)
        visit_row(0, y, [&](const auto *row) {
            for (int x = 0; x < cols(0); ++x)
                n += widened(row[x]).empty();
        });
    return n;
}

uint64_t MinMaxPyramid::bytes() const
{
    uint64_t n = 0;
    for (size_t level = 0; level < dims_.size(); ++level)
        n += uint64_t(dims_[level].first) * uint64_t(dims_[level].second) *
             (level == 0 && shared_base_ ? shared_base_->record_bytes() : sizeof(ZRange));
    return n;
}

std::vector<ZRange> MinMaxPyramid::flattened() const
{
    std::vector<ZRange> all;
    all.reserve(size_t(bytes() / sizeof(ZRange)));
    for (int level = 0; level < levels(); ++level)
        for (int y = 0; y < rows(level); ++y)
            for (int x = 0; x < cols(level); ++x)
                all.push_back(node(level, x, y));
    return all;
}

} // namespace sbrt
