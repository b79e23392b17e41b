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

std::vector<uint32_t> gpu_page_table_head(const StackPages &pages)
{
    const int block_cols = (pages.cols() + pages.block_size() - 1) / pages.block_size();
    return {uint32_t(pages.block_size()), uint32_t(block_cols),
            gpu_mark_words(pages.block_count()), 0};
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
