/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A model's stacks decoded block by block, in a bounded cache
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/stack_pages.hpp"

#include <algorithm>
#include <cmath>

#include "model/column_ranges.hpp"
#include "model/model.hpp"
#include "util/available_memory.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// Bytes of blocks dropped, at least, before the heap is released.
constexpr uint64_t RELEASE_AFTER_DROPPED = uint64_t(32) << 20;

/// `size`, where it is a block size (at least 1).
int checked_block_size(int size)
{
    if (size < 1)
        fail("StackPages: the block size must be positive");
    return size;
}

double mib(uint64_t bytes)
{
    return std::ceil(double(bytes) / (1 << 20) * 10) / 10;
}

} // namespace

StackPages::StackPages(const Frame &frame, int block_size, Decoder decode,
                       uint64_t budget_bytes, const char *budget_name, unsigned threads,
                       ColumnRangeArray ranges, bool ranges_needed, bool compact_ranges)
    : rows_(frame.rows), cols_(frame.cols), size_(checked_block_size(block_size)),
      block_rows_((frame.rows + block_size - 1) / block_size),
      block_cols_((frame.cols + block_size - 1) / block_size), decode_(std::move(decode)),
      budget_(budget_bytes), opened_budget_(budget_bytes), budget_name_(budget_name),
      slots_(size_t(block_rows_) * size_t(block_cols_))
{
    if (!ranges.empty()) { // stored beside the stacks
        if (ranges.size() != frame.cells())
            fail("StackPages: ", ranges.size(), " column ranges for ", frame.cells(),
                 " cells");
        // (branch-free loops: vectorised)
        if (const CompactRange *compact = ranges.compact_data()) {
            uint16_t highest = 0; // an empty column's high is 0
            for (size_t i = 0; i < ranges.size(); ++i)
                highest = std::max(highest, compact[i].high);
            highest_top_ = highest;
        }
        else {
            const ZRange *wide = ranges.wide_data();
            float highest = 0;
            for (size_t i = 0; i < ranges.size(); ++i)
                highest = std::max(highest, wide[i].low <= wide[i].high ? wide[i].high : 0.0f);
            highest_top_ = highest;
        }
    }
    else if (!ranges_needed) {
        return; // none held
    }
    else {
        // every block read once; those read first stay while they fit,
        // none is dropped for a later one (the rays will ask for their own)
        // (held as they are read: the budget counted them so)
        auto read_all = [&](auto read) {
            std::vector<double> tops(slots_.size(), 0.0);
            for_each_row(block_count(), threads, [&](int b) {
                tops[size_t(b)] = block_column_ranges(*fetch(b, false), cols_, read);
            });
            highest_top_ = *std::max_element(tops.begin(), tops.end());
            return ColumnRangeArray(std::move(read));
        };
        ranges = compact_ranges ? read_all(CompactRanges(frame.cells()))
                                : read_all(std::vector<ZRange>(frame.cells()));
    }
    ranges_ = std::make_shared<const ColumnRangeArray>(std::move(ranges));
}

void StackPages::fail_no_ranges()
{
    fail("the paged model was opened without its column ranges (a reader of single "
         "columns); the empty-space skipping and the framing need them");
}

StackBlock StackPages::block_cells(int b) const
{
    StackBlock cells;
    cells.first_row = b / block_cols_ * size_;
    cells.first_col = b % block_cols_ * size_;
    cells.rows = std::min(size_, rows_ - cells.first_row);
    cells.cols = std::min(size_, cols_ - cells.first_col);
    return cells;
}

void StackPages::set_block_materials(std::vector<std::vector<uint16_t>> materials)
{
    if (!materials.empty() && materials.size() != slots_.size())
        fail("StackPages: the materials of ", materials.size(), " blocks for ", slots_.size());
    block_materials_ = std::move(materials);
}

bool StackPages::block_may_hold(int b, const std::vector<uint8_t> &marked) const
{
    if (block_materials_.empty())
        return true;
    for (uint16_t m : block_materials_[size_t(b)])
        if (m < marked.size() && marked[m])
            return true;
    return false;
}

void StackPages::for_each_block(unsigned threads,
                                const std::function<void(const StackBlock &)> &visit) const
{
    for_each_row(block_count(), threads, [&](int b) { visit(*block(b)); });
}

std::shared_ptr<const StackBlock> StackPages::held(int b) const
{
    const std::lock_guard<std::mutex> lock(cache_);
    Slot &slot = slots_[size_t(b)];
    if (slot.block)
        used_.splice(used_.begin(), used_, slot.used);
    return slot.block;
}

void StackPages::hold(int b, std::shared_ptr<const StackBlock> block, bool evict) const
{
    bool release = false;
    {
        const std::lock_guard<std::mutex> lock(cache_);
        if (!evict && held_ + block->bytes() > budget_)
            return;
        held_ += block->bytes();
        Slot &slot = slots_[size_t(b)];
        slot.block = std::move(block);
        used_.push_front(b);
        slot.used = used_.begin();
        // never the block just decoded (readers holding a dropped block
        // keep it until they let go)
        drop_over_budget(1);
        peak_ = std::max(peak_, held_);
        // the heap's holes left by dropped blocks go back to the system
        // each time an eighth of the budget was dropped (32 MiB at least:
        // a reader of single columns holds a block a thread, and would
        // trim the heap every few blocks)
        if (dropped_ > std::max(budget_ / 8, RELEASE_AFTER_DROPPED)) {
            dropped_ = 0;
            release = true;
        }
    }
    if (release) // (not under the lock: other threads go on reading)
        release_free_heap();
}

void StackPages::drop_over_budget(size_t keep) const
{
    while (held_ > budget_ && used_.size() > keep) {
        Slot &last = slots_[size_t(used_.back())];
        held_ -= last.block->bytes();
        dropped_ += last.block->bytes();
        last.block.reset();
        used_.pop_back();
    }
}

void StackPages::set_budget_bytes(uint64_t bytes) const
{
    {
        const std::lock_guard<std::mutex> lock(cache_);
        budget_ = bytes;
        drop_over_budget(0);
        dropped_ = 0; // released now
    }
    release_free_heap();
}

std::shared_ptr<const StackBlock> StackPages::block(int b) const
{
    return fetch(b, true);
}

std::shared_ptr<const StackBlock> StackPages::fetch(int b, bool evict) const
{
    if (b < 0 || b >= block_count())
        fail("StackPages: block ", b, " of ", block_count());
    if (auto block = held(b))
        return block;
    Slot &slot = slots_[size_t(b)];
    const std::lock_guard<std::mutex> decoding(slot.decoding);
    if (auto block = held(b)) // decoded while this thread waited
        return block;
    auto block = std::make_shared<const StackBlock>(decode_(b));
    ++decodes_;
    if (block->bytes() > opened_budget_)
        fail("the memory budget (", budget_name_, ") of ", mib(opened_budget_), " MiB is less than "
             "one block of the model takes decoded (", mib(block->bytes()), " MiB): give ",
             budget_name_, " at least ", uint64_t(std::ceil(double(block->bytes()) / (1 << 20))) + 1);
    hold(b, block, evict);
    return block;
}

PagingFigures StackPages::figures() const
{
    const std::lock_guard<std::mutex> lock(cache_);
    return {decodes_.load(), held_, peak_};
}

} // namespace sbrt
