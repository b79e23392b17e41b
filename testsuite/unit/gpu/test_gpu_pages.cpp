/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The GPU's page atlas without a GPU: a block's words give each
 *            cell's stack as the model holds it; the atlas's free ranges;
 *            which blocks stay and which go when it is full
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>

#include <gtest/gtest.h>

#include "gpu/gpu_pages.hpp"
#include "paged_case.hpp"

using namespace sbrt;

namespace {

/// Each cell's stack of `block` read from its words as the shader reads
/// them (shaders/common/layout.glsl, SBRT_PAGED) against `model`'s.
void expect_stacks_of_the_model(const StackBlock &block, const std::vector<uint32_t> &words,
                                bool compact, const Model &model)
{
    const uint32_t cells = uint32_t(block.rows * block.cols);
    const uint32_t records_at = (cells + 2u) & ~1u;
    for (int r = 0; r < block.rows; ++r)
        for (int c = 0; c < block.cols; ++c) {
            const uint32_t cell = uint32_t(r * block.cols + c);
            const uint32_t first = words[cell], last = words[cell + 1];
            const uint64_t whole = model.cell_index(block.first_row + r, block.first_col + c);
            const StackRange want = model.stack(whole);
            ASSERT_EQ(last - first, want.size()) << "cell " << cell;
            for (uint32_t j = 0; j < last - first; ++j) {
                const Interval iv = model.intervals()[want.begin + j];
                uint32_t material = 0;
                float top = 0;
                if (compact) {
                    const uint32_t w = words[records_at + first + j];
                    material = w & 0xffffu;
                    top = float(w >> 16);
                }
                else {
                    material = words[records_at + 2 * (first + j)];
                    std::memcpy(&top, &words[records_at + 2 * (first + j) + 1], 4);
                }
                EXPECT_EQ(material, iv.material);
                EXPECT_EQ(top, iv.top);
            }
        }
}

} // namespace

TEST(GpuPages, ABlocksWordsGiveEachCellsStackInEitherForm)
{
    const sbrt_test::PagedCase c;
    const Model paged = c.paged(uint64_t(1) << 30);
    const StackPages &pages = *paged.pages();
    ASSERT_EQ(pages.block_count(), 30);
    for (int b = 0; b < pages.block_count(); ++b) {
        const std::shared_ptr<const StackBlock> block = pages.block(b);
        for (bool compact : {true, false}) {
            const std::vector<uint32_t> words = gpu_block_words(*block, compact);
            const uint32_t cells = uint32_t(block->rows * block->cols);
            EXPECT_EQ(words.size(), ((cells + 2u) & ~1u) + block->intervals.size() *
                                                                (compact ? 1 : 2));
            expect_stacks_of_the_model(*block, words, compact, c.model);
        }
    }
    // the head: blocks of 8, 6 a row (45 columns), 30 blocks' bits a word
    EXPECT_EQ(gpu_page_table_head(pages), (std::vector<uint32_t>{8, 6, 1, 0}));
}

TEST(GpuPages, AWideIntervalRefusesTheCompactForm)
{
    StackBlock block;
    block.rows = block.cols = 1;
    block.index = StackIndex::from_sizes(std::vector<uint32_t>{1}.data(), 1);
    Intervals wide;
    wide.push_back(Interval{1, 2.5f});
    block.intervals = IntervalArray(std::move(wide));
    EXPECT_THROW(gpu_block_words(block, true), Error);
    EXPECT_EQ(gpu_block_words(block, false).size(), 4u);
}

TEST(GpuPages, TheAtlasGivesEvenRangesAndMergesWhatComesBack)
{
    AtlasSpace space(100);
    const auto a = space.take(31), b = space.take(20), c = space.take(40);
    ASSERT_TRUE(a && b && c);
    EXPECT_EQ(*a, 0u);
    EXPECT_EQ(*b, 32u); // 31 rounded up to even
    EXPECT_EQ(*c, 52u);
    EXPECT_EQ(space.free_words(), 8u);
    EXPECT_FALSE(space.take(10));
    space.give_back(*a, 31);
    space.give_back(*c, 40);
    EXPECT_FALSE(space.take(50)); // two free ranges of 32 and 48
    space.give_back(*b, 20);
    EXPECT_EQ(space.free_words(), 100u);
    EXPECT_EQ(space.take(100), std::optional<uint64_t>(0));
}

TEST(GpuPages, AFullAtlasDropsTheLeastRecentlyUsedNeverTheFramesOwn)
{
    PageResidency r(6, 40);
    std::vector<int> dropped;
    EXPECT_TRUE(r.place(0, 10, dropped));
    EXPECT_TRUE(r.place(1, 10, dropped));
    EXPECT_TRUE(r.place(2, 10, dropped));
    EXPECT_TRUE(r.place(3, 10, dropped));
    // the frame's own blocks stay: no room for a fifth
    EXPECT_FALSE(r.place(4, 10, dropped));
    EXPECT_TRUE(dropped.empty());
    r.begin_frame();
    r.mark_read(2);
    r.mark_read(3);
    r.begin_frame();
    r.mark_read(3);
    // 0 and 1 were last used two frames ago, 2 one frame ago
    EXPECT_TRUE(r.place(4, 20, dropped));
    EXPECT_EQ(dropped, (std::vector<int>{0, 1}));
    EXPECT_FALSE(r.holds(0));
    EXPECT_TRUE(r.holds(2));
    dropped.clear();
    EXPECT_TRUE(r.place(5, 10, dropped));
    EXPECT_EQ(dropped, (std::vector<int>{2}));
    EXPECT_EQ(r.held_blocks(), 3);
    EXPECT_EQ(r.held_words(), 40u);
    // a block larger than the atlas is never placed
    dropped.clear();
    r.begin_frame();
    EXPECT_FALSE(r.place(0, 42, dropped));
}

TEST(GpuPages, ABlockNoDroppingCouldMakeRoomForDropsNone)
{
    PageResidency r(4, 40);
    std::vector<int> dropped;
    EXPECT_TRUE(r.place(0, 10, dropped));
    EXPECT_TRUE(r.place(1, 10, dropped));
    r.begin_frame();
    r.mark_read(0);
    // 20 free and 10 that may go: 32 words cannot be made room for
    EXPECT_FALSE(r.place(2, 32, dropped));
    EXPECT_TRUE(dropped.empty());
    EXPECT_TRUE(r.holds(1));
    EXPECT_TRUE(r.found_no_room(2));
    // 30 can: block 1 goes, next to the free words
    EXPECT_TRUE(r.place(3, 30, dropped));
    EXPECT_EQ(dropped, (std::vector<int>{1}));
    // the next frame seeks room for block 2 again
    r.begin_frame();
    EXPECT_FALSE(r.found_no_room(2));
}
