/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Min-max pyramid over the cells for empty-space skipping: per
 *            node of 2^L x 2^L cells, the lowest bottom and the highest top
 *            of the material left to draw (empty: nothing to draw)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MINMAX_PYRAMID_HPP
#define SBRT_MINMAX_PYRAMID_HPP

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "model/column_range_array.hpp"
#include "model/model.hpp"
#include "model/z_range.hpp"

namespace sbrt {

/// \brief The `narrow` of a pyramid that leaves every cell as its stack
/// has it (no clip plane, no overlay): level 0 is then not walked to
/// find that out.
struct KeepEveryCell {
    void operator()(int, int, ZRange &) const {}
};

/// \brief Level 0 is the grid (x from the west, y from the south, as the
/// tracer's local frame); level L + 1 halves level L in x and y (rounding
/// up) down to one node. Built in time linear in the intervals.
class MinMaxPyramid {
public:
    MinMaxPyramid() = default;
    /// From the model's stacks, the materials marked in `hidden` (per
    /// material index; empty: none) left out; `narrow(x, y, range)` may
    /// narrow or empty a cell's range (cells cut away by clip planes,
    /// cells with overlays). A paged model's level 0 is its column ranges,
    /// shared, never copied: what is hidden or narrowed narrows only the
    /// levels above (level_0_wider()), made block by block (`narrow` is
    /// then called on several threads).
    template <typename Narrow>
    MinMaxPyramid(const Model &model, const Narrow &narrow,
                  const std::vector<uint8_t> &hidden = {})
    {
        const Frame &f = model.frame();
        if (model.is_paged() && model.pages()->has_column_ranges()) {
            shared_base_ = model.pages()->shared_column_ranges();
            // (for KeepEveryCell, the overload below answers at once)
            if (hidden.empty() && narrows_none(f, *shared_base_, narrow))
                build(f.cols, f.rows, {});
            else
                build_over_shared(f.cols, f.rows, narrowed_level_1(model, narrow, hidden));
            return;
        }
        std::vector<ZRange> cells = cell_ranges(model, hidden);
        for (int y = 0; y < f.rows; ++y)
            for (int x = 0; x < f.cols; ++x)
                narrow(x, y, cells[size_t(y) * f.cols + x]);
        build(f.cols, f.rows, std::move(cells));
    }

    int levels() const { return int(dims_.size()); }
    int cols(int level) const { return dims_[level].first; }
    int rows(int level) const { return dims_[level].second; }
    ZRange node(int level, int x, int y) const
    {
        if (level == 0 && shared_base_) // row by row from the north
            return (*shared_base_)[size_t(dims_[0].second - 1 - y) * dims_[0].first + x];
        return levels_[level][size_t(y) * dims_[level].first + x];
    }
    /// Calls f with row y of `level` (x from the west): a const ZRange *,
    /// or a const CompactRange * where level 0 is compact column ranges
    /// (read with widened()).
    template <typename F>
    decltype(auto) visit_row(int level, int y, F &&f) const
    {
        if (level == 0 && shared_base_)
            return shared_base_->visit([&](const auto *first) {
                return f(first + size_t(dims_[0].second - 1 - y) * dims_[0].first);
            });
        return f(levels_[level].data() + size_t(y) * dims_[level].first);
    }
    /// Whether level 0 is a paged model's column ranges, shared.
    bool shares_column_ranges() const { return shared_base_ != nullptr; }
    /// Whether level 0 (a paged model's column ranges) may hold more than
    /// the levels above it: hidden strata and narrowed cells are left out
    /// of those only. A cell's level 0 then bounds where material lies,
    /// a node above where material drawn lies.
    bool level_0_wider() const { return level_0_wider_; }
    /// Cells (level 0) with nothing to draw (where level_0_wider(): with
    /// no material at all).
    uint64_t empty_cells() const;
    /// Bytes of all levels (as a GPU buffer would hold them).
    uint64_t bytes() const;
    /// Every level one after the other, level 0 first (the GPU's layout).
    std::vector<ZRange> flattened() const;

private:
    /// Each cell's range of the intervals drawn (not EMPTY, not marked in
    /// `hidden`): from the bottom of the lowest to the top of the highest.
    static std::vector<ZRange> cell_ranges(const Model &model,
                                           const std::vector<uint8_t> &hidden);
    /// Whether `narrow` leaves every cell of `ranges` (row by row from the
    /// north) as it is.
    template <typename Narrow>
    static bool narrows_none(const Frame &f, const ColumnRangeArray &ranges,
                             const Narrow &narrow)
    {
        for (int y = 0; y < f.rows; ++y)
            for (int x = 0; x < f.cols; ++x) {
                const ZRange cell = ranges[size_t(f.rows - 1 - y) * f.cols + x];
                ZRange narrowed = cell;
                narrow(x, y, narrowed);
                if (narrowed.low != cell.low || narrowed.high != cell.high)
                    return false;
            }
        return true;
    }
    static bool narrows_none(const Frame &, const ColumnRangeArray &, const KeepEveryCell &)
    {
        return true;
    }
    /// The ranges of block `b` of a paged model (its cells row by row
    /// from its north edge), the materials marked in `hidden` left out:
    /// the stored column ranges where it holds none of them.
    static std::vector<ZRange> block_ranges(const Model &model, int b,
                                            const std::vector<uint8_t> &hidden);
    /// Calls visit(b) for every block of a paged model, on all cores.
    static void for_each_block(const Model &model, const std::function<void(int)> &visit);
    /// Level 1 over a paged model's cells, `hidden` left out and each
    /// cell's range narrowed by `narrow`, made block by block.
    template <typename Narrow>
    static std::vector<ZRange> narrowed_level_1(const Model &model, const Narrow &narrow,
                                                const std::vector<uint8_t> &hidden)
    {
        const Frame &f = model.frame();
        const int up_cols = (f.cols + 1) / 2;
        std::vector<ZRange> up(size_t(up_cols) * size_t((f.rows + 1) / 2));
        std::mutex merging;
        for_each_block(model, [&](int b) {
            std::vector<ZRange> ranges = block_ranges(model, b, hidden);
            const StackBlock cells = model.pages()->block_cells(b);
            // (a cell's y counts from the south, its row from the north)
            size_t k = 0;
            for (int row = cells.first_row; row < cells.first_row + cells.rows; ++row)
                for (int col = cells.first_col; col < cells.first_col + cells.cols; ++col)
                    narrow(col, f.rows - 1 - row, ranges[k++]);
            const std::lock_guard<std::mutex> lock(merging);
            k = 0;
            for (int row = cells.first_row; row < cells.first_row + cells.rows; ++row)
                for (int col = cells.first_col; col < cells.first_col + cells.cols; ++col)
                    widen(up[size_t((f.rows - 1 - row) / 2) * up_cols + col / 2], ranges[k++]);
        });
        return up;
    }
    /// `node` widened to hold `cell` too.
    static void widen(ZRange &node, const ZRange &cell)
    {
        if (!cell.empty())
            node = node.empty() ? cell
                                : ZRange{std::min(node.low, cell.low),
                                         std::max(node.high, cell.high)};
    }
    /// Level 0 from `cells` (y from the south), or the shared base where
    /// `cells` is empty; then the levels above it.
    void build(int cols, int rows, std::vector<ZRange> cells);
    /// Level 0 the shared base of cols x rows cells, level 1 `level_1`
    /// (narrower), then the levels above them.
    void build_over_shared(int cols, int rows, std::vector<ZRange> level_1);
    /// The levels above the last one made.
    void build_above();

    /// levels_[0] is empty where level 0 is shared_base_
    std::vector<std::vector<ZRange>> levels_;
    std::shared_ptr<const ColumnRangeArray> shared_base_;
    std::vector<std::pair<int, int>> dims_;
    bool level_0_wider_ = false; ///< the levels above are narrower
};

} // namespace sbrt

#endif
