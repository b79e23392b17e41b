/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   voxels -> SBRT -> file -> SBRT -> voxels is identical
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <sys/stat.h>

#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "util/error.hpp"
#include "format/format.hpp"
#include "test_support.hpp"
#include "builders/voxel_builder.hpp"
#include "builders/voxel_expander.hpp"

using namespace sbrt;
using sbrt_test::random_voxels;

namespace {

std::vector<int32_t> expand(const Model &m, const Frame &target)
{
    VoxelExpander expander(m, target);
    std::vector<int32_t> out(target.voxels());
    for (int z = 0; z < target.depths; ++z)
        expander.next_slice(out.data() + size_t(z) * target.cells());
    return out;
}

} // namespace

TEST(VoxelRoundTrip, RandomColumnsSurviveBuildEncodeDecodeExpand)
{
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const auto v = random_voxels(seed, 3 + seed % 7, 2 + seed % 5,
                                     1 + int(seed * 5 % 37));
        const Model m = sbrt_test::build_model(v);
        m.validate();
        const auto bytes = encode_stacks_v1(m);
        const Model back = decode_stacks(bytes.data(), bytes.size(), "mem");
        EXPECT_EQ(expand(back, v.frame), v.classes) << "seed " << seed;
    }
}

TEST(VoxelRoundTrip, IntervalsAreMaximalRuns)
{
    const auto v = random_voxels(99, 6, 5, 40);
    const Model m = sbrt_test::build_model(v);
    // count runs independently: every class change along a column, and a
    // trailing null run is not stored
    uint64_t runs = 0;
    for (uint64_t c = 0; c < v.frame.cells(); ++c) {
        int last_solid = -1;
        for (int z = 0; z < v.frame.depths; ++z)
            if (v.classes[z * v.frame.cells() + c] != NULL_CLASS)
                last_solid = z;
        for (int z = 0; z <= last_solid; ++z)
            if (z == 0 || v.classes[z * v.frame.cells() + c] !=
                              v.classes[(z - 1) * v.frame.cells() + c])
                ++runs;
    }
    EXPECT_EQ(m.intervals().size(), runs);
}

TEST(VoxelRoundTrip, StatsOfAHandMadeModel)
{
    // 2 cells x 4 depths, bottom up; figures counted by hand:
    //   cell 0: 5, 5, null, 9  -> 5 (2 voxels), EMPTY (cave), 9: 3 intervals
    //   cell 1: 9, null, null, null -> 9 (trailing air not stored): 1
    sbrt_test::Voxels v;
    v.frame.rows = 1;
    v.frame.cols = 2;
    v.frame.depths = 4;
    v.classes = {5, 9, 5, NULL_CLASS, NULL_CLASS, NULL_CLASS, 9, NULL_CLASS};
    const Stats s = sbrt_test::build_model(v).stats();
    EXPECT_EQ(s.voxels, 8u);
    EXPECT_EQ(s.voxel_bytes, 32u);    // 8 FCELL voxels
    EXPECT_EQ(s.intervals, 4u);
    EXPECT_EQ(s.solid_intervals, 3u); // all but the cave
    EXPECT_EQ(s.max_stack, 3u);
    EXPECT_DOUBLE_EQ(s.mean_stack, 2.0);
    // 2 counts of 4 bytes + 4 intervals of 8 + 3 materials (EMPTY, 5, 9) of 8
    EXPECT_EQ(s.sbrt_bytes, 64u);
    EXPECT_DOUBLE_EQ(s.compression_percent, -100.0); // twice the voxels' size
}

TEST(VoxelRoundTrip, StatsAgreeWithTheVoxelsAndTheModelInMemory)
{
    const auto v = random_voxels(7, 10, 8, 30);
    const Model m = sbrt_test::build_model(v);
    const Stats s = m.stats();

    // brute force from the source voxels: walk each column bottom up,
    // a new interval at every class change, the trailing null run not stored
    const uint64_t cells = uint64_t(v.frame.rows) * v.frame.cols;
    uint64_t intervals = 0, solid = 0;
    uint32_t max_stack = 0;
    std::set<int32_t> classes;
    for (uint64_t c = 0; c < cells; ++c) {
        std::vector<int32_t> column;
        for (int z = 0; z < v.frame.depths; ++z)
            column.push_back(v.classes[z * cells + c]);
        while (!column.empty() && column.back() == NULL_CLASS)
            column.pop_back();
        uint32_t runs = 0;
        for (size_t z = 0; z < column.size(); ++z) {
            if (column[z] != NULL_CLASS)
                classes.insert(column[z]);
            if (z > 0 && column[z] == column[z - 1])
                continue;
            ++runs;
            solid += column[z] != NULL_CLASS;
        }
        intervals += runs;
        max_stack = std::max(max_stack, runs);
    }
    ASSERT_GT(intervals, cells); // the seed gives stacks of several runs
    EXPECT_EQ(s.voxels, 10u * 8u * 30u);
    EXPECT_EQ(s.voxel_bytes, 10u * 8u * 30u * 4u);
    EXPECT_EQ(s.intervals, intervals);
    EXPECT_EQ(s.solid_intervals, solid);
    EXPECT_LT(s.solid_intervals, s.intervals); // the seed has caves
    EXPECT_EQ(s.max_stack, max_stack);
    EXPECT_DOUBLE_EQ(s.mean_stack, double(intervals) / double(cells));

    // the bytes are those of the model in memory: 4 per interval (voxel
    // tops, compact), a count byte per cell (padded to groups of 16 cells)
    // and 8 per group, 8 per material
    ASSERT_TRUE(m.intervals().is_compact());
    EXPECT_EQ(s.interval_bytes, intervals * 4);
    EXPECT_EQ(s.index_bytes, (cells + 15) / 16 * (16 + 8));
    const uint64_t memory_bytes = s.interval_bytes + s.index_bytes + m.materials().size() * 8;
    EXPECT_EQ(s.sbrt_bytes, memory_bytes);
    // the materials the file holds: EMPTY and one per class of the voxels
    EXPECT_EQ(m.materials().size(), classes.size() + 1);
    EXPECT_DOUBLE_EQ(s.compression_percent,
                     100.0 * (1.0 - double(memory_bytes) / (10 * 8 * 30 * 4)));
}

TEST(VoxelRoundTrip, SingleVoxelLayersAndCaves)
{
    sbrt_test::Voxels v;
    v.frame.rows = 1;
    v.frame.cols = 1;
    v.frame.depths = 7;
    // bottom up: 3, null (cave), 4, 4, 5 (one voxel), null, null (air)
    v.classes = {3, NULL_CLASS, 4, 4, 5, NULL_CLASS, NULL_CLASS};
    const Model m = sbrt_test::build_model(v);
    ASSERT_EQ(m.intervals().size(), 4u);
    EXPECT_EQ(m.intervals()[1].material, EMPTY);
    EXPECT_FLOAT_EQ(m.intervals()[3].top, 5.0f);
    EXPECT_EQ(expand(m, v.frame), v.classes);
}

TEST(VoxelRoundTrip, ExpansionInAnotherRegionSamplesNearestCell)
{
    const auto v = random_voxels(5, 4, 4, 8);
    const Model m = sbrt_test::build_model(v);
    Frame half = v.frame; // same extent, every other column and depth
    half.cols = 2;
    half.depths = 4;
    const auto out = expand(m, half);
    for (int z = 0; z < 4; ++z)
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 2; ++c) {
                // centre of target cell (r, c, z) lies in source (r, 2c+1, 2z+1)
                const int32_t want =
                    v.classes[((2 * z + 1) * 4 + r) * 4 + 2 * c + 1];
                EXPECT_EQ(out[(z * 4 + r) * 2 + c], want);
            }
}

TEST(VoxelRoundTrip, WriteAndReadDirectoryKeepsLabelsAndColours)
{
    const auto v = random_voxels(11, 5, 6, 12, 3);
    std::vector<Material> legend(1);
    legend[0].id = -13; // class 1 * 7 - 20
    legend[0].label = "clay: silty";
    legend[0].red = 10;
    legend[0].has_color = true;
    VoxelStackBuilder builder(v.frame);
    for (int z = 0; z < v.frame.depths; ++z)
        builder.add_slice(v.slice(z));
    const Model m = builder.finish(legend);
    const std::string dir = sbrt_test::temp_dir("rw") + "/model";
    write_sbrt(dir, m, "test history\n");
    const Model back = read_sbrt(dir);
    const int64_t k = back.find_material(-13);
    ASSERT_GT(k, 0);
    EXPECT_EQ(back.materials()[k].label, "clay: silty");
    EXPECT_EQ(back.materials()[k].red, 10);
    EXPECT_TRUE(back.materials()[k].has_color);
    EXPECT_EQ(expand(back, v.frame), v.classes);
    remove_tree(dir.substr(0, dir.rfind('/')));
}

TEST(VoxelRoundTrip, WrongSliceCountIsAnError)
{
    const auto v = random_voxels(3, 2, 2, 4);
    VoxelStackBuilder builder(v.frame);
    builder.add_slice(v.slice(0));
    EXPECT_THROW(builder.finish(), Error);
}

TEST(VoxelRoundTrip, GridsBeyondThe32BitIndicesAreClearErrors)
{
    // 70000 x 70000 cells overflow the 32-bit offsets and cell indices:
    // refused with the limit, before anything is allocated for them
    Frame f;
    f.rows = f.cols = 70000;
    f.north = f.east = 70000;
    try {
        VoxelStackBuilder builder(f);
        FAIL() << "a grid of 4.9e9 cells was accepted";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("too many cells"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("2^31-1"), std::string::npos) << e.what();
    }
    f.rows = 1;
    f.depths = (1 << 24) + 1; // heights no longer exact in float32
    EXPECT_THROW(VoxelStackBuilder{f}, Error);
}
