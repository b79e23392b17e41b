/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The coarse level of detail (scene/level_of_detail): the factor
 *            rule, centre sampling of exact stacks, the frame unchanged, no
 *            level for small models; stored as stacks_lod and read back
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "format/format.hpp"
#include "frame/coordinate_frame.hpp"
#include "scene/level_of_detail.hpp"
#include "util/error.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

Frame grid(int rows, int cols)
{
    Frame f;
    f.rows = rows;
    f.cols = cols;
    return f;
}

/// Every stack of `m` at (row, col) as (material, top) pairs.
std::vector<std::pair<uint32_t, float>> stack_of(const Model &m, int row, int col)
{
    std::vector<std::pair<uint32_t, float>> out;
    for (const Interval &iv : m.stack_intervals(m.cell_index(row, col)))
        out.emplace_back(iv.material, iv.top);
    return out;
}

} // namespace

TEST(LevelOfDetail, FactorRule)
{
    // under 512 x 512 cells: none
    EXPECT_EQ(level_of_detail_factor(grid(511, 512)), 1);
    EXPECT_EQ(level_of_detail_factor(grid(100, 2000)), 1);
    // 512 x 512: the smallest factor of two already fits
    EXPECT_EQ(level_of_detail_factor(grid(512, 512)), 2);
    EXPECT_EQ(level_of_detail_factor(grid(1414, 1414)), 2); // 707 x 707 = 499,849
    EXPECT_EQ(level_of_detail_factor(grid(1415, 1415)), 4); // 708 x 708 > 500,000
    // the national model: 662 x 703 = 465,386 cells
    EXPECT_EQ(level_of_detail_factor(grid(2647, 2812)), 4);
    // 16 times national: still at most 500,000 cells
    const Frame big = grid(10588, 11248);
    const int factor = level_of_detail_factor(big);
    EXPECT_EQ(factor, 16);
    EXPECT_LE(uint64_t((big.rows + factor - 1) / factor) * ((big.cols + factor - 1) / factor),
              LOD_MAX_CELLS);
}

TEST(LevelOfDetail, CentreSamplingKeepsTheFrameAndExactStacks)
{
    const sbrt_test::Voxels v = sbrt_test::random_voxels(11, 37, 29, 9);
    const Model fine = sbrt_test::build_model(v);
    for (int factor : {2, 4, 8}) {
        const Model coarse = coarsened(fine, factor);
        coarse.validate();
        const Frame &f = coarse.frame(), &g = fine.frame();
        EXPECT_EQ(f.rows, (g.rows + factor - 1) / factor);
        EXPECT_EQ(f.cols, (g.cols + factor - 1) / factor);
        // the same extent, vertical frame, materials
        EXPECT_EQ(f.north, g.north);
        EXPECT_EQ(f.south, g.south);
        EXPECT_EQ(f.east, g.east);
        EXPECT_EQ(f.west, g.west);
        EXPECT_EQ(f.bottom, g.bottom);
        EXPECT_EQ(f.top, g.top);
        EXPECT_EQ(f.depths, g.depths);
        ASSERT_EQ(coarse.materials().size(), fine.materials().size());
        for (size_t i = 0; i < fine.materials().size(); ++i)
            EXPECT_EQ(coarse.materials()[i].id, fine.materials()[i].id);
        // each cell: the fine cell under its centre, by map coordinates
        for (int r = 0; r < f.rows; ++r)
            for (int c = 0; c < f.cols; ++c) {
                const double x = f.west + (c + 0.5) * f.ew_res();
                const double y = f.north - (r + 0.5) * f.ns_res();
                const auto cell = cell_of_point(g, x, y);
                ASSERT_TRUE(cell.has_value());
                ASSERT_EQ(stack_of(coarse, r, c), stack_of(fine, cell->row, cell->col))
                    << "factor " << factor << " cell " << r << "," << c;
            }
    }
}

TEST(LevelOfDetail, FactorOneIsACopyAndBelowOneIsRefused)
{
    const Model fine = sbrt_test::build_model(sbrt_test::random_voxels(3, 6, 7, 5));
    const Model same = coarsened(fine, 1);
    EXPECT_EQ(same.frame().rows, 6);
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 7; ++c)
            EXPECT_EQ(stack_of(same, r, c), stack_of(fine, r, c));
    EXPECT_THROW(coarsened(fine, 0), Error);
}

TEST(LevelOfDetail, StoredBesideTheStacksAndReadBack)
{
    char pattern[] = "/tmp/sbrt_lod_XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    const std::string dir = std::string(pattern) + "/m";
    const Model fine = sbrt_test::build_model(sbrt_test::random_voxels(5, 20, 24, 6));
    // without a coarse model: no member, no level
    write_sbrt(dir, fine, "h\n");
    EXPECT_FALSE(read_sbrt_lod(dir).has_value());
    const Model coarse = coarsened(fine, 4);
    write_sbrt(dir, fine, "h\n", {}, {}, &coarse);
    const auto level = read_sbrt_lod(dir);
    ASSERT_TRUE(level.has_value());
    EXPECT_EQ(level->factor(), 4);
    EXPECT_EQ(level->exact.rows, 20);
    EXPECT_EQ(level->model.frame().rows, 5);
    EXPECT_EQ(level->exact_top_local, highest_top_local(fine));
    EXPECT_EQ(stack_of(level->model, 2, 3), stack_of(coarse, 2, 3));
    // the exact model reads as before
    EXPECT_EQ(read_sbrt(dir).frame().rows, 20);
    // a damaged member is an error naming it
    const std::string member = dir + "/stacks_lod";
    FILE *f = std::fopen(member.c_str(), "r+b");
    ASSERT_NE(f, nullptr);
    std::fseek(f, 0, SEEK_END);
    std::fseek(f, std::ftell(f) / 2, SEEK_SET); // in a block or a table
    std::fputc(0x5a, f);
    std::fclose(f);
    try {
        read_sbrt_lod(dir);
        ADD_FAILURE() << "a damaged stacks_lod was read";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("stacks_lod"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read_sbrt(dir).frame().rows, 20); // the exact model is untouched
    std::system(("rm -rf " + std::string(pattern)).c_str());
}
