/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The GPU's page atlas without a GPU: a block's words give each
 *            cell's stack as the model holds it; the atlas's free ranges;
 *            which blocks stay and which go when it is full
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>

#include <gtest/gtest.h>

#include "gpu/gpu_layout.hpp"
#include "gpu/gpu_pages.hpp"
#include "model/column_ranges.hpp"
#include "scene/minmax_pyramid.hpp"
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

TEST(GpuPages, AColumnsPageGivesEachCellsTopIntervalAndRangeInEitherForm)
{
    const sbrt_test::PagedCase c;
    const Model paged = c.paged(uint64_t(1) << 30, true);
    const StackPages &pages = *paged.pages();
    const std::vector<Interval> tops = column_tops(c.model);
    const std::vector<ZRange> ranges = column_ranges(c.model);
    const int cols = c.model.frame().cols;
    for (int b = 0; b < pages.block_count(); ++b) {
        const StackBlock cells = pages.block_cells(b);
        for (bool compact : {true, false}) {
            const std::vector<uint32_t> words = gpu_column_page_words(pages, b, compact);
            const uint32_t per = gpu_column_words(compact);
            ASSERT_EQ(words.size(), size_t(cells.rows) * size_t(cells.cols) * per);
            for (int r = 0; r < cells.rows; ++r)
                for (int k = 0; k < cells.cols; ++k) {
                    const uint32_t *w = &words[size_t(r * cells.cols + k) * per];
                    const size_t cell = size_t(cells.first_row + r) * size_t(cols) +
                                        size_t(cells.first_col + k);
                    float bottom, low, high;
                    uint32_t material;
                    if (compact) {
                        material = w[0] & 0xffffu;
                        bottom = float(w[0] >> 16);
                        low = float(w[1] & 0xffffu);
                        high = float(w[1] >> 16);
                    }
                    else {
                        material = w[0];
                        std::memcpy(&bottom, &w[1], 4);
                        std::memcpy(&low, &w[2], 4);
                        std::memcpy(&high, &w[3], 4);
                    }
                    EXPECT_EQ(material, tops[cell].material) << "cell " << cell;
                    EXPECT_EQ(bottom, tops[cell].top) << "cell " << cell;
                    EXPECT_EQ(low, ranges[cell].low) << "cell " << cell;
                    EXPECT_EQ(high, ranges[cell].high) << "cell " << cell;
                }
        }
    }
    // the columns' pages after the blocks': 60 pages' bits in two words
    EXPECT_EQ(gpu_page_table_head(pages, true), (std::vector<uint32_t>{8, 6, 2, 30}));
    // a model without its tops has no columns' pages
    const Model untopped = c.paged(uint64_t(1) << 30);
    EXPECT_THROW(gpu_column_page_words(*untopped.pages(), 0, true), Error);
}

TEST(GpuPages, APyramidFromALevelOnHoldsThoseLevelsAlone)
{
    const sbrt_test::PagedCase c;
    const MinMaxPyramid pyramid(c.model, KeepEveryCell{});
    ASSERT_GE(pyramid.levels(), 4);
    for (int first : {0, 1, 3}) {
        const std::vector<uint32_t> words = make_gpu_pyramid(pyramid, first);
        EXPECT_EQ(words.size() * 4, gpu_pyramid_bytes(pyramid, first));
        EXPECT_EQ(words[3], uint32_t(first));
        for (int level = 0; level < pyramid.levels(); ++level) {
            const uint32_t *head = &words[size_t(4 * level)];
            if (level < first) {
                EXPECT_EQ(head[1], 0u);
                EXPECT_EQ(head[2], 0u);
                continue;
            }
            ASSERT_EQ(head[1], uint32_t(pyramid.cols(level)));
            ASSERT_EQ(head[2], uint32_t(pyramid.rows(level)));
            const ZRange *nodes = reinterpret_cast<const ZRange *>(
                &words[size_t(4 * GPU_MAX_PYRAMID_LEVELS) + 2 * size_t(head[0])]);
            for (int y = 0; y < pyramid.rows(level); ++y)
                for (int x = 0; x < pyramid.cols(level); ++x) {
                    const ZRange n = nodes[size_t(y) * size_t(head[1]) + size_t(x)];
                    EXPECT_EQ(n.low, pyramid.node(level, x, y).low);
                    EXPECT_EQ(n.high, pyramid.node(level, x, y).high);
                }
        }
    }
    EXPECT_LT(gpu_pyramid_bytes(pyramid, 1) * 3, gpu_pyramid_bytes(pyramid));
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
