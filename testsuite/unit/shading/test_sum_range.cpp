/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   sbrt::sum_range (issue 51, item 2): the least and greatest
 *            sum of channels over the voxels that have one (fills
 *            skipped), against the sums of the source values; one channel
 *            its stated range; no value at all is said
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "format/mapped_file.hpp"
#include "shading/property_paint.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

constexpr float FILL = -127;

/// Random voxels with two channels that move against each other: a + b is
/// 40 + level, far inside the sum of their ranges; a has fills.
struct SumFixture {
    sbrt_test::Voxels voxels;
    Model model;
    sbrt_test::Source source;
    std::shared_ptr<const PropertyChannels> channels;
};

SumFixture fixture(unsigned seed, const std::string &dir, bool all_fill = false)
{
    SumFixture fx;
    fx.voxels = sbrt_test::random_voxels(seed, 9 + seed % 5, 7 + seed % 4, 12 + seed % 9, 6);
    fx.model = sbrt_test::build_model(fx.voxels);
    const Frame &f = fx.voxels.frame;
    std::mt19937 rng(seed);
    fx.source.assign(2, std::vector<float>(f.voxels()));
    for (size_t i = 0; i < f.voxels(); ++i) {
        const float level = float(i / f.cells());
        const float a = float(rng() % 41);
        fx.source[0][i] = all_fill || rng() % 11 == 0 ? FILL : a;
        fx.source[1][i] = 40 - a + level;
    }
    ChannelInfo a, b;
    a.name = "ha";
    a.has_fill = true;
    a.fill = FILL;
    b.name = "hb";
    const std::string path = dir + "/sum_range" + std::to_string(seed) + (all_fill ? "f" : "");
    sbrt_test::write_channels(path, fx.model, fx.source, {a, b}, 4);
    fx.channels = std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(path), path, fx.model);
    return fx;
}

} // namespace

TEST(SumRange, IsTheRangeOfTheSumsPerVoxel)
{
    const std::string dir = sbrt_test::temp_dir("sum_range");
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const SumFixture fx = fixture(seed, dir);
        const Frame &f = fx.voxels.frame;
        double want_low = std::numeric_limits<double>::infinity(), want_high = -want_low;
        for (uint64_t cell = 0; cell < f.cells(); ++cell) {
            const ColumnSpan span = fx.channels->span(cell);
            for (uint32_t level = span.lo; level < span.hi; ++level) {
                const float a = sbrt_test::source_value(fx.source, f, 0, cell, level);
                if (a == FILL)
                    continue;
                const double sum = a + sbrt_test::source_value(fx.source, f, 1, cell, level);
                want_low = std::min(want_low, sum);
                want_high = std::max(want_high, sum);
            }
        }
        ASSERT_LT(want_low, want_high) << seed;
        double low = 0, high = 0;
        ASSERT_TRUE(sum_range(*fx.channels, {0, 1}, low, high)) << seed;
        EXPECT_EQ(low, want_low) << seed;
        EXPECT_EQ(high, want_high) << seed;
        // narrower than the sum of the channels' ranges
        const ChannelInfo &a = fx.channels->info(0), &b = fx.channels->info(1);
        EXPECT_LT(a.min + b.min, low) << seed;
        EXPECT_GT(a.max + b.max, high) << seed;
        // one channel: its stated range
        ASSERT_TRUE(sum_range(*fx.channels, {1}, low, high));
        EXPECT_EQ(low, b.min);
        EXPECT_EQ(high, b.max);
    }
}

TEST(SumRange, NoValueAnywhereIsSaid)
{
    const std::string dir = sbrt_test::temp_dir("sum_range");
    const SumFixture fx = fixture(3, dir, true);
    double low = 1, high = 2;
    EXPECT_FALSE(sum_range(*fx.channels, {0, 1}, low, high));
    EXPECT_EQ(low, 0);
    EXPECT_EQ(high, 0);
}
