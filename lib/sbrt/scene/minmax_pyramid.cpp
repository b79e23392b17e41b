/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Min-max pyramid over the cells
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/minmax_pyramid.hpp"

#include <algorithm>

namespace sbrt {

std::vector<ZRange> MinMaxPyramid::cell_ranges(const Model &model,
                                               const std::vector<uint8_t> &hidden)
{
    const Frame &f = model.frame();
    std::vector<ZRange> cells(f.cells());
    model.intervals().visit([&](const auto *records) {
        using Record = RecordOf<decltype(records)>;
        const auto drawn = [&](const Record &r) {
            return r.material != EMPTY && (hidden.empty() || !hidden[r.material]);
        };
        for (int row = 0; row < f.rows; ++row)
            for (int col = 0; col < f.cols; ++col) {
                const StackRange stack = model.stack(model.cell_index(row, col));
                const Record *first = records + stack.begin, *last = records + stack.end;
                // leading EMPTY (or hidden) intervals lift the lowest
                // bottom; a stack ends with material (no trailing EMPTY),
                // so without hidden strata the top is its last interval's
                const Record *low = first;
                while (low != last && !drawn(*low))
                    ++low;
                if (low == last)
                    continue;
                const Record *high = last - 1;
                while (!drawn(*high))
                    --high;
                const size_t y = size_t(f.rows - 1 - row);
                cells[y * f.cols + col] = {low == first ? 0.0f : float((low - 1)->top),
                                           float(high->top)};
            }
    });
    return cells;
}

void MinMaxPyramid::build(int cols, int rows, std::vector<ZRange> cells)
{
    levels_.push_back(std::move(cells));
    dims_.push_back({cols, rows});
    while (cols > 1 || rows > 1) {
        const int up_cols = (cols + 1) / 2, up_rows = (rows + 1) / 2;
        std::vector<ZRange> up(size_t(up_cols) * up_rows);
        const std::vector<ZRange> &down = levels_.back();
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < cols; ++x) {
                const ZRange &c = down[size_t(y) * cols + x];
                if (c.empty())
                    continue;
                ZRange &n = up[size_t(y / 2) * up_cols + x / 2];
                n = n.empty() ? c
                              : ZRange{std::min(n.low, c.low), std::max(n.high, c.high)};
            }
        levels_.push_back(std::move(up));
        dims_.push_back({up_cols, up_rows});
        cols = up_cols;
        rows = up_rows;
    }
}

uint64_t MinMaxPyramid::empty_cells() const
{
    if (levels_.empty())
        return 0;
    return uint64_t(std::count_if(levels_[0].begin(), levels_[0].end(),
                                  [](const ZRange &r) { return r.empty(); }));
}

uint64_t MinMaxPyramid::bytes() const
{
    uint64_t n = 0;
    for (const auto &level : levels_)
        n += level.size() * sizeof(ZRange);
    return n;
}

std::vector<ZRange> MinMaxPyramid::flattened() const
{
    std::vector<ZRange> all;
    for (const auto &level : levels_)
        all.insert(all.end(), level.begin(), level.end());
    return all;
}

} // namespace sbrt
