/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A paged model on the GPU (issue 49): the blocks that rays
 *            reach, within a budget, in one atlas of words found through a
 *            page table (shaders/common/layout.glsl, SBRT_PAGED); which
 *            block lies where, and which go when the atlas is full
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GPU_PAGES_HPP
#define SBRT_GPU_PAGES_HPP

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "model/stack_pages.hpp"

namespace sbrt {

/// A page table's word for a block that is not in the atlas.
constexpr uint32_t GPU_PAGE_MISSING = 0xffffffffu;

/// Words before the page table's entries (`buffer PageTable`): the block
/// size in cells, blocks a row of blocks, words of each half of the marks
/// (`buffer PageMarks`: the pages wanted, then those read), and the number
/// of the first columns' page (the block count; 0 where there are none).
constexpr uint32_t GPU_PAGE_TABLE_HEAD = 4;

/// The most words an atlas holds: record indices stay below 2^31 - 16,
/// where the shaders' stack of a column's top interval lies (layout.glsl,
/// TOP_STACK), and a search's sum of two indices does not wrap.
constexpr uint64_t GPU_MAX_ATLAS_WORDS = 0x7fffffe0u;

/// Words of the page marks' halves for `blocks` blocks: a bit a block.
inline uint32_t gpu_mark_words(int blocks) { return uint32_t((blocks + 31) / 32); }

/// The pages of `pages` on the GPU: a block each, and with
/// `column_pages` a page of each block's columns after them.
inline int gpu_page_count(const StackPages &pages, bool column_pages)
{
    return pages.block_count() * (column_pages ? 2 : 1);
}

/// The page table's head for `pages`; with `column_pages`, pages of the
/// blocks' columns follow the blocks' (the fourth word: the first's
/// number, block_count; else 0).
std::vector<uint32_t> gpu_page_table_head(const StackPages &pages, bool column_pages = false);

/// Words of a column in a page of columns: its top interval, then its
/// range; a word each where `compact` (material | bottom << 16, low |
/// high << 16), else two each (material and the bottom's float bits, the
/// low's and the high's).
inline uint32_t gpu_column_words(bool compact) { return compact ? 2 : 4; }

/// \brief The page of block `b`'s columns (shaders/common/layout.glsl,
/// SBRT_COLUMN_PAGES): for each of its cells, row by row, its top interval
/// (StackPages::column_tops) and its range of material (column_ranges, the
/// pyramid's level 0), gpu_column_words each. A model too large for the
/// GPU to hold these for every column at once: a ray reads its block's
/// columns page, not its block, where it meets only a top interval.
/// Throws sbrt::Error where the model holds neither, or where `compact`
/// is asked of a height that is no voxel boundary.
std::vector<uint32_t> gpu_column_page_words(const StackPages &pages, int b, bool compact);

/// \brief A block's words in the atlas: for each of its cells, row by row,
/// where its stack starts (records from the block's first), and where the
/// last ends; then from the next even word the intervals as the model
/// holds them on the GPU: a word each (`compact`: material | top << 16), or
/// two (material, the bits of the float top). The shader finds a cell's
/// stack from the block's base word alone (layout.glsl, stack_range).
/// Throws sbrt::Error where `compact` is asked of an interval that is not.
std::vector<uint32_t> gpu_block_words(const StackBlock &block, bool compact);

/// \brief Free words of an atlas: ranges taken first fit and given back
/// (merged with their neighbours); every range starts on an even word, so
/// that two-word intervals stay aligned.
class AtlasSpace {
public:
    explicit AtlasSpace(uint64_t words);
    /// Where `words` now lie, or nothing where no free range holds them.
    std::optional<uint64_t> take(uint64_t words);
    /// Frees the range take() gave for `words` at `at`.
    void give_back(uint64_t at, uint64_t words);
    uint64_t free_words() const { return free_words_; }
    uint64_t words() const { return words_; }

private:
    static uint64_t even(uint64_t words) { return (words + 1) & ~uint64_t(1); }
    uint64_t words_, free_words_;
    std::map<uint64_t, uint64_t> free_; ///< first word -> words, disjoint
};

/// \brief Which blocks the atlas holds, and where: a frame's blocks (read
/// or placed since begin_frame) stay; others go least recently used first
/// when a block needs their room.
class PageResidency {
public:
    PageResidency(int blocks, uint64_t atlas_words);

    /// A new frame: the blocks of the last may go again.
    void begin_frame()
    {
        ++frame_;
        frame_words_ = 0;
    }
    /// Block b was read in this frame (its bit among the marks read).
    void mark_read(int b);
    /// Room for block b of `words` words, made by dropping blocks not used
    /// in this frame (listed in `dropped`); its base word, or nothing
    /// where even that leaves too little room (it stays missing, and no
    /// block is dropped where their words together would not make room).
    std::optional<uint32_t> place(int b, uint64_t words, std::vector<int> &dropped);
    /// Whether block b found no room in this frame (its place is not
    /// sought again before the next).
    bool found_no_room(int b) const { return slots_[size_t(b)].no_room == frame_; }

    /// Block b's base word in the atlas, or GPU_PAGE_MISSING.
    uint32_t base(int b) const { return slots_[size_t(b)].base; }
    bool holds(int b) const { return base(b) != GPU_PAGE_MISSING; }
    int held_blocks() const { return held_; }
    uint64_t held_words() const { return space_.words() - space_.free_words(); }
    uint64_t atlas_words() const { return space_.words(); }

private:
    using ByUse = std::multimap<uint64_t, int>;
    struct Slot {
        uint32_t base = GPU_PAGE_MISSING;
        uint64_t words = 0;
        uint64_t used = 0;    ///< the frame it was last used in
        uint64_t no_room = 0; ///< the frame it last found no room in
        ByUse::iterator at; ///< its place in by_use_, where held
    };
    /// Held block b used in this frame: its place among the held by use.
    void use(int b);
    void drop(int b);

    AtlasSpace space_;
    std::vector<Slot> slots_;
    /// held blocks by the frame they were last used in (oldest first)
    ByUse by_use_;
    uint64_t frame_ = 1;
    int held_ = 0;
    uint64_t frame_words_ = 0; ///< words of the blocks this frame used
};

} // namespace sbrt

#endif
