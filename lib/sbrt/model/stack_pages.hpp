/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A model's stacks held by blocks of cells, each decoded when a
 *            reader first reaches it and kept in a cache of bounded bytes
 *            (least recently used dropped first): a view pays the memory of
 *            the blocks it touches, not of the model (issue 49)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACK_PAGES_HPP
#define SBRT_STACK_PAGES_HPP

#include <atomic>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <vector>

#include "model/column_range_array.hpp"
#include "model/interval_array.hpp"
#include "model/stack_index.hpp"
#include "model/z_range.hpp"

namespace sbrt {

struct Frame;

/// \brief The stacks of one block: cells [first_row, first_row + rows) x
/// [first_col, first_col + cols) of the model's grid (row 0 north), row by
/// row, checked as Model::validate checks a model's.
struct StackBlock {
    int first_row = 0, first_col = 0, rows = 0, cols = 0;
    StackIndex index;
    IntervalArray intervals;

    /// The stack of the model's cell (row, col), which the block holds.
    StackRange range(int row, int col) const
    {
        return index.range(uint64_t(row - first_row) * uint64_t(cols) +
                           uint64_t(col - first_col));
    }
    uint64_t bytes() const
    {
        return index.bytes() + uint64_t(intervals.size()) * intervals.record_bytes();
    }
};

/// \brief What a model's pages did so far.
struct PagingFigures {
    uint64_t decodes = 0;    ///< blocks decoded (again after being dropped too)
    uint64_t held_bytes = 0; ///< decoded blocks held now
    uint64_t peak_bytes = 0; ///< the most held at once
};

/// \brief The blocks of a model (square tiles of `block_size` cells, row
/// by row of blocks, as a format 2 file stores them), decoded on demand.
/// Safe to read from many threads: a block is decoded once however many
/// ask for it at the same time.
class StackPages {
public:
    /// Decodes and checks block `b` (throws sbrt::Error where it is
    /// damaged).
    using Decoder = std::function<StackBlock(int b)>;

    /// Blocks stay held up to `budget_bytes`. Each column's range of
    /// material is `ranges` where given (as stored beside the stacks), else
    /// read from every block once (on `threads` threads, 0: all cores),
    /// as u16 pairs where `compact_ranges` (every top a voxel boundary a
    /// u16 holds, as the file's summary says), unless `ranges_needed` is
    /// false (a reader of single columns: none is then held). Throws
    /// sbrt::Error where a block alone takes more than the budget
    /// (`budget_name` names the option that sets it).
    StackPages(const Frame &frame, int block_size, Decoder decode, uint64_t budget_bytes,
               const char *budget_name, unsigned threads, ColumnRangeArray ranges = {},
               bool ranges_needed = true, bool compact_ranges = false);

    int rows() const { return rows_; }
    int cols() const { return cols_; }
    int block_size() const { return size_; }
    int block_count() const { return block_rows_ * block_cols_; }
    int block_of(int row, int col) const
    {
        return row / size_ * block_cols_ + col / size_;
    }
    /// Block `b`, decoded where it is not held; it stays valid while the
    /// pointer is kept, dropped from the cache or not.
    std::shared_ptr<const StackBlock> block(int b) const;
    /// Calls visit(block) for every block, on `threads` threads.
    void for_each_block(unsigned threads,
                        const std::function<void(const StackBlock &)> &visit) const;
    /// The cells of block `b` (its first row and column, rows, cols),
    /// known without decoding it.
    StackBlock block_cells(int b) const;
    /// Each block's materials (indices, not EMPTY), as the file's block
    /// summaries list them; none given: every block may hold any.
    void set_block_materials(std::vector<std::vector<uint16_t>> materials);
    /// Whether block `b` may hold a material that `marked` (per material
    /// index) marks: true where its materials are not known.
    bool block_may_hold(int b, const std::vector<uint8_t> &marked) const;

    /// Whether each column's range is held (column_ranges()).
    bool has_column_ranges() const { return ranges_ != nullptr; }
    /// Each cell's range of material (row by row, row 0 north; EMPTY left
    /// out): MinMaxPyramid's cells without hidden strata. Throws
    /// sbrt::Error where they are not held.
    const ColumnRangeArray &column_ranges() const
    {
        if (!ranges_)
            fail_no_ranges();
        return *ranges_;
    }
    /// The same, shared (a pyramid's level 0).
    std::shared_ptr<const ColumnRangeArray> shared_column_ranges() const { return ranges_; }
    /// The highest top of any stack (local units), 0 where all are empty;
    /// throws sbrt::Error where the column ranges are not held.
    double highest_top_local() const
    {
        if (!ranges_)
            fail_no_ranges();
        return highest_top_;
    }
    /// Each column's top interval (model/column_ranges.hpp column_tops:
    /// per cell its material and, in `top`, its bottom), where held: a ray
    /// that stays above that bottom needs no block.
    void set_column_tops(IntervalArray tops) { tops_ = std::move(tops); }
    bool has_column_tops() const { return !tops_.empty(); }
    const IntervalArray &column_tops() const { return tops_; }
    uint64_t budget_bytes() const { return budget_; }
    /// Holds the blocks within `bytes` from now on, the least recently
    /// used dropped at once where more are held; between views (no reader
    /// is fetching blocks). Const as the cache is: the model's stacks stay
    /// what they are.
    void set_budget_bytes(uint64_t bytes) const;
    PagingFigures figures() const;

private:
    struct Slot {
        std::mutex decoding; ///< held while this block is decoded
        std::shared_ptr<const StackBlock> block;
        std::list<int>::iterator used; ///< its place in used_, where held
    };
    /// The held block b, moved to the front of used_; null where not held.
    std::shared_ptr<const StackBlock> held(int b) const;
    /// Holds block b, the least recently used dropped where the budget
    /// is passed; with `evict` false, only where it fits as it is.
    void hold(int b, std::shared_ptr<const StackBlock> block, bool evict) const;
    std::shared_ptr<const StackBlock> fetch(int b, bool evict) const;
    /// Drops the least recently used blocks while more than the budget is
    /// held, keeping the `keep` most recent; cache_ held by the caller.
    void drop_over_budget(size_t keep) const;
    [[noreturn]] static void fail_no_ranges();

    int rows_, cols_, size_, block_rows_, block_cols_;
    Decoder decode_;
    mutable uint64_t budget_; ///< set_budget_bytes changes it between views
    /// as opened: a block larger is refused (below it, a smaller budget
    /// set later still holds the block just decoded)
    const uint64_t opened_budget_;
    const char *budget_name_;
    std::shared_ptr<const ColumnRangeArray> ranges_;
    double highest_top_ = 0;
    std::vector<std::vector<uint16_t>> block_materials_; ///< empty: not known
    IntervalArray tops_; ///< empty: not held

    mutable std::vector<Slot> slots_;
    mutable std::mutex cache_;      ///< guards the slots' blocks, used_, held_
    mutable std::list<int> used_;   ///< held blocks, most recently used first
    mutable uint64_t held_ = 0, peak_ = 0;
    mutable uint64_t dropped_ = 0; ///< bytes dropped since the heap was last released
    mutable std::atomic<uint64_t> decodes_{0};
};

/// \brief The block a walk is in, kept while it stays there: one look-up
/// in the cache per block a ray enters, not per cell.
class StackPin {
public:
    const StackBlock &at(const StackPages &pages, int row, int col)
    {
        const int b = pages.block_of(row, col);
        if (b != id_ || !block_) {
            block_ = pages.block(b);
            id_ = b;
        }
        return *block_;
    }

private:
    int id_ = -1;
    std::shared_ptr<const StackBlock> block_;
};

} // namespace sbrt

#endif
