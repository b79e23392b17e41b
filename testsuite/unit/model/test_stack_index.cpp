/****************************************************************************
 * MODULE:    r3.sbrt unit tests
 * PURPOSE:   The compact model in memory: stack index (counts and group
 *            offsets) and 4-byte intervals where exact
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "util/error.hpp"
#include "format/format_v2.hpp"
#include "builders/horizon_builder.hpp"
#include "model/model.hpp"
#include "model/stack_index.hpp"
#include "test_support.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

/// Every cell's range against the running sum of the sizes.
void expect_ranges(const StackIndex &index, const std::vector<uint32_t> &sizes)
{
    ASSERT_EQ(index.cells(), sizes.size());
    uint64_t begin = 0;
    for (uint64_t c = 0; c < sizes.size(); ++c) {
        const StackRange r = index.range(c);
        ASSERT_EQ(r.begin, begin) << "cell " << c;
        ASSERT_EQ(r.end, begin + sizes[c]) << "cell " << c;
        ASSERT_EQ(index.size(c), sizes[c]) << "cell " << c;
        begin += sizes[c];
    }
    EXPECT_EQ(index.total(), begin);
}

} // namespace

TEST(StackIndex, RangesAreTheRunningSumsInEveryCountWidth)
{
    std::mt19937 rng(7);
    const struct {
        uint32_t longest;
        unsigned bytes;
    } widths[] = {{255, 1}, {256, 2}, {65535, 2}, {65536, 4}, {100000, 4}};
    for (const auto &w : widths)
        for (uint64_t cells : {1u, 7u, 8u, 9u, 15u, 16u, 17u, 1001u}) {
            std::uniform_int_distribution<uint32_t> size(0, w.longest);
            std::vector<uint32_t> sizes(cells);
            for (uint32_t &s : sizes)
                s = rng() % 4 == 0 ? 0 : size(rng);
            sizes[cells / 2] = w.longest; // the longest sets the width
            const StackIndex index = StackIndex::from_sizes(sizes.data(), cells);
            EXPECT_EQ(index.count_bytes(), w.bytes) << w.longest;
            EXPECT_EQ(index.max_size(), w.longest);
            expect_ranges(index, sizes);
            // and the same from offsets
            std::vector<uint64_t> offsets(cells + 1, 0);
            for (uint64_t c = 0; c < cells; ++c)
                offsets[c + 1] = offsets[c] + sizes[c];
            expect_ranges(StackIndex::from_offsets(offsets.data(), cells), sizes);
        }
}

TEST(StackIndex, FullCountBytesSumWithoutCarryingIntoTheNextLane)
{
    // fifteen counts of 255 before the last cell of a group: 3825
    std::vector<uint32_t> sizes(48, 255);
    sizes[20] = 0;
    expect_ranges(StackIndex::from_sizes(sizes.data(), sizes.size()), sizes);
}

TEST(StackIndex, OffsetsAreSixtyFourBits)
{
    // 80,000 stacks of 60,000 intervals: 4.8 G, past 2^32 - 1 from cell 71,583
    std::vector<uint32_t> sizes(80000, 60000);
    const StackIndex index = StackIndex::from_sizes(sizes.data(), sizes.size());
    EXPECT_EQ(index.total(), 80000ull * 60000ull);
    EXPECT_EQ(index.range(79999).begin, 79999ull * 60000ull);
    EXPECT_EQ(index.range(71583).end, 71584ull * 60000ull); // > 2^32
}

TEST(StackIndex, TakesAtMostTwoBytesACellWithByteCounts)
{
    for (uint64_t cells : {16u, 64u, 4096u, 1000003u}) {
        const std::vector<uint32_t> sizes(cells, 24);
        const StackIndex index = StackIndex::from_sizes(sizes.data(), cells);
        // a byte per cell and 8 per group of 16 cells: 1.5 a cell
        EXPECT_EQ(index.bytes(), (cells + 15) / 16 * 24) << cells;
        EXPECT_LE(index.bytes(), 2 * cells) << cells;
    }
}

TEST(IntervalArray, PacksExactlyWhereEveryTopIsAVoxelBoundary)
{
    Intervals wide = {{1, 3}, {0, 7}, {65535, 65535}};
    IntervalArray packed = IntervalArray::packed(wide);
    ASSERT_TRUE(packed.is_compact());
    EXPECT_EQ(packed.record_bytes(), 4u);
    for (size_t i = 0; i < wide.size(); ++i) {
        EXPECT_EQ(packed[i].material, wide[i].material);
        EXPECT_EQ(packed[i].top, wide[i].top);
    }
    // a fractional top, a top past 16 bits, a material past 16 bits
    const Intervals no[] = {{{1, 2.5f}}, {{1, 65536}}, {{65536, 4}}};
    for (const Intervals &n : no) {
        const IntervalArray kept = IntervalArray::packed(n);
        EXPECT_FALSE(kept.is_compact());
        EXPECT_EQ(kept[0].material, n[0].material);
        EXPECT_EQ(kept[0].top, n[0].top);
    }
}

TEST(CompactModel, VoxelModelsTakeFourBytesAnIntervalAndHorizonsEight)
{
    const Model voxels = build_model(random_voxels(3, 20, 30, 40));
    EXPECT_TRUE(voxels.intervals().is_compact());
    const Stats s = voxels.stats();
    EXPECT_EQ(s.interval_bytes, s.intervals * 4);
    EXPECT_LE(s.index_bytes, 2 * voxels.frame().cells());
    // a continuous horizon keeps its float tops
    Frame f;
    f.rows = 2;
    f.cols = 3;
    f.depths = 10;
    f.top = 10;
    Material a, b;
    a.id = 1;
    b.id = 2;
    HorizonStackBuilder horizons(f, {a, b});
    const std::vector<double> low(3, 3.25), high(3, 7.5), base(3, NAN);
    for (int row = 0; row < f.rows; ++row)
        horizons.add_row({low.data(), high.data()}, base.data());
    const Model h = horizons.finish();
    EXPECT_FALSE(h.intervals().is_compact());
    EXPECT_EQ(h.stats().interval_bytes, h.stats().intervals * 8);
}

TEST(CompactModel, TracesAsTheWideModelDoes)
{
    const Model compact = build_model(random_voxels(11, 24, 31, 50));
    const Model wide = widened(compact);
    ASSERT_TRUE(compact.intervals().is_compact());
    ASSERT_FALSE(wide.intervals().is_compact());
    const Camera camera = top_camera(compact.frame(), 10);
    const Image a = render_cpu(compact, camera, 1, 2), b = render_cpu(wide, camera, 1, 2);
    ASSERT_EQ(a.material.size(), b.material.size());
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(a.rgb, b.rgb);
}

TEST(CompactModel, AnIndexNotStartingAtZeroIsRefused)
{
    Frame f;
    f.cols = 2;
    Intervals two = {{1, 1}, {1, 1}};
    EXPECT_THROW(Model(f, {Material(), Material()}, std::vector<uint32_t>{5, 6, 7}, two),
                 Error);
    // nor one that falls (a negative stack size)
    EXPECT_THROW(Model(f, {Material(), Material()}, std::vector<uint32_t>{0, 2, 1}, two),
                 Error);
    const Model fine(f, {Material(), Material()}, std::vector<uint32_t>{0, 1, 2}, two);
    fine.validate();
}

TEST(CompactModel, MoreThan65535DepthsStayWideAndRoundTrip)
{
    // one column of 65536 and one of 70001 layers: tops past 16 bits
    for (int depths : {65535, 65536, 70001}) {
        Voxels v;
        v.frame.rows = 1;
        v.frame.cols = 3;
        v.frame.depths = depths;
        v.frame.top = depths;
        v.classes.assign(v.frame.voxels(), NULL_CLASS);
        for (int z = 0; z < depths; ++z) {
            v.classes[size_t(z) * 3] = 1 + (z / 3) % 2;      // runs of 3
            v.classes[size_t(z) * 3 + 2] = z < depths - 7 ? 4 : 5;
        }
        const Model m = build_model(v);
        EXPECT_EQ(m.intervals().is_compact(), depths <= 65535) << depths;
        EXPECT_EQ(m.stack_intervals(2).back().top, float(depths));
        const Model back = decode_stacks_v2(encode_stacks_v2(m).data(),
                                            encode_stacks_v2(m).size(), "test");
        EXPECT_EQ(back.intervals().is_compact(), depths <= 65535);
        ASSERT_EQ(back.intervals().size(), m.intervals().size());
        for (size_t i = 0; i < m.intervals().size(); ++i) {
            ASSERT_EQ(back.intervals()[i].material, m.intervals()[i].material) << i;
            ASSERT_EQ(back.intervals()[i].top, m.intervals()[i].top) << i;
        }
        for (uint64_t c = 0; c < 3; ++c)
            EXPECT_EQ(back.stack_size(c), m.stack_size(c));
    }
}
