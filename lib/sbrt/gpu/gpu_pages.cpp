/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A paged model's blocks in the GPU's atlas
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu/gpu_pages.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>

#include "model/interval_array.hpp"
#include "util/error.hpp"

namespace sbrt {

std::vector<uint32_t> gpu_page_table_head(const StackPages &pages, bool column_pages)
{
    const int block_cols = (pages.cols() + pages.block_size() - 1) / pages.block_size();
    return {uint32_t(pages.block_size()), uint32_t(block_cols),
            gpu_mark_words(gpu_page_count(pages, column_pages)),
            column_pages ? uint32_t(pages.block_count()) : 0u};
}

namespace {

/// A height as a compact word's half: a voxel boundary (the empty range's
/// 1 and 0 too).
uint32_t compact_height(float z, const StackBlock &cells)
{
    if (!(z >= 0 && z <= 65535 && z == float(uint32_t(z))))
        fail("the columns of the block at row ", cells.first_row, ", column ",
             cells.first_col, " reach a height that is no voxel boundary, in a model held "
             "compact on the GPU");
    return uint32_t(z);
}

uint32_t float_bits(float z)
{
    uint32_t bits;
    std::memcpy(&bits, &z, 4);
    return bits;
}

} // namespace

std::vector<uint32_t> gpu_column_page_words(const StackPages &pages, int b, bool compact)
{
    if (!pages.has_column_tops())
        fail("a page of columns needs the model's column tops");
    const ColumnRangeArray &ranges = pages.column_ranges();
    const IntervalArray &tops = pages.column_tops();
    const StackBlock cells = pages.block_cells(b);
    const uint32_t per_column = gpu_column_words(compact);
    std::vector<uint32_t> words(size_t(cells.rows) * size_t(cells.cols) * per_column);
    uint32_t *w = words.data();
    for (int row = cells.first_row; row < cells.first_row + cells.rows; ++row)
        for (int col = cells.first_col; col < cells.first_col + cells.cols; ++col, w += per_column) {
            const size_t cell = size_t(row) * size_t(pages.cols()) + size_t(col);
            const Interval top = tops[cell];
            const ZRange range = ranges[cell];
            if (compact) {
                w[0] = top.material | compact_height(top.top, cells) << 16;
                w[1] = compact_height(range.low, cells) | compact_height(range.high, cells) << 16;
                continue;
            }
            w[0] = top.material;
            w[1] = float_bits(top.top);
            w[2] = float_bits(range.low);
            w[3] = float_bits(range.high);
        }
    return words;
}

std::vector<uint32_t> gpu_block_words(const StackBlock &block, bool compact)
{
    const uint64_t cells = uint64_t(block.rows) * uint64_t(block.cols);
    const uint64_t records_at = (cells + 2) & ~uint64_t(1); // cells + 1 offsets, even
    const uint64_t intervals = block.intervals.size();
    if (intervals > GPU_PAGE_MISSING / 2)
        fail("a block of ", intervals, " intervals is too large for the GPU's atlas");
    std::vector<uint32_t> words(records_at + intervals * (compact ? 1 : 2), 0u);
    for (uint64_t c = 0; c < cells; ++c)
        words[c] = uint32_t(block.index.range(c).begin);
    words[cells] = uint32_t(intervals);
    uint32_t *records = words.data() + records_at;
    if (compact && block.intervals.is_compact()) {
        std::memcpy(records, block.intervals.compact_data(), intervals * 4);
        return words;
    }
    for (uint64_t i = 0; i < intervals; ++i) {
        const Interval iv = block.intervals[i];
        if (compact) {
            if (!fits_compact(iv))
                fail("block at row ", block.first_row, ", column ", block.first_col,
                     " holds an interval whose top is no voxel boundary, in a model held "
                     "compact on the GPU");
            records[i] = iv.material | uint32_t(iv.top) << 16;
            continue;
        }
        records[2 * i] = iv.material;
        std::memcpy(&records[2 * i + 1], &iv.top, 4);
    }
    return words;
}

AtlasSpace::AtlasSpace(uint64_t words) : words_(words & ~uint64_t(1)), free_words_(words_)
{
    if (words_ > 0)
        free_[0] = words_;
}

std::optional<uint64_t> AtlasSpace::take(uint64_t words)
{
    words = even(words);
    for (auto it = free_.begin(); it != free_.end(); ++it) {
        if (it->second < words)
            continue;
        const uint64_t at = it->first, left = it->second - words;
        free_.erase(it);
        if (left > 0)
            free_[at + words] = left;
        free_words_ -= words;
        return at;
    }
    return std::nullopt;
}

void AtlasSpace::give_back(uint64_t at, uint64_t words)
{
    words = even(words);
    free_words_ += words;
    auto next = free_.lower_bound(at);
    // merged with the free range after it and the one before
    if (next != free_.end() && at + words == next->first) {
        words += next->second;
        next = free_.erase(next);
    }
    if (next != free_.begin()) {
        const auto before = std::prev(next);
        if (before->first + before->second == at) {
            before->second += words;
            return;
        }
    }
    free_[at] = words;
}

PageResidency::PageResidency(int blocks, uint64_t atlas_words)
    : space_(std::min<uint64_t>(atlas_words, GPU_MAX_ATLAS_WORDS)), slots_(size_t(blocks))
{
}

void PageResidency::use(int b)
{
    Slot &slot = slots_[size_t(b)];
    if (slot.used == frame_)
        return;
    by_use_.erase(slot.at);
    slot.used = frame_;
    slot.at = by_use_.emplace(frame_, b);
    frame_words_ += slot.words;
}

void PageResidency::mark_read(int b)
{
    if (holds(b))
        use(b);
}

void PageResidency::drop(int b)
{
    Slot &slot = slots_[size_t(b)];
    by_use_.erase(slot.at);
    space_.give_back(slot.base, slot.words);
    slot.base = GPU_PAGE_MISSING;
    --held_;
}

std::optional<uint32_t> PageResidency::place(int b, uint64_t words, std::vector<int> &dropped)
{
    if (holds(b))
        return base(b);
    Slot &slot = slots_[size_t(b)];
    std::optional<uint64_t> at = space_.take(words);
    // the least recently used go first, never this frame's; none where
    // all of them would not make room
    if (!at && space_.free_words() + (held_words() - frame_words_) >= words)
        while (!at && !by_use_.empty() && by_use_.begin()->first < frame_) {
            const int old = by_use_.begin()->second;
            drop(old);
            dropped.push_back(old);
            at = space_.take(words);
        }
    if (!at) {
        slot.no_room = frame_;
        return std::nullopt;
    }
    slot.base = uint32_t(*at);
    slot.words = words;
    slot.used = frame_;
    slot.at = by_use_.emplace(frame_, b);
    frame_words_ += words;
    ++held_;
    return slot.base;
}

} // namespace sbrt
