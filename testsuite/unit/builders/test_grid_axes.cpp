/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   File axes: roles from CF clues, regular axes from centres,
 *            missing values, column by column building
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <gtest/gtest.h>

#include "builders/column_builder.hpp"
#include "util/error.hpp"
#include "builders/grid_axes.hpp"
#include "builders/missing_values.hpp"
#include "test_support.hpp"
#include "builders/voxel_expander.hpp"

using namespace sbrt;

namespace {

AxisRole role(const char *name, const char *axis = "", const char *standard = "",
              const char *positive = "")
{
    AxisClues c;
    c.name = name;
    c.axis = axis;
    c.standard_name = standard;
    c.positive = positive;
    return axis_role(c);
}

std::string error_of(const std::vector<double> &centres, bool negate = false)
{
    try {
        regular_axis(centres, negate, "dim");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(GridAxes, RolesFromAxisStandardNamePositiveAndName)
{
    EXPECT_EQ(role("a", "X"), AxisRole::easting);
    EXPECT_EQ(role("lat", "x"), AxisRole::easting); // axis wins over the name
    EXPECT_EQ(role("b", "", "projection_y_coordinate"), AxisRole::northing);
    EXPECT_EQ(role("lev", "", "", "down"), AxisRole::vertical);
    EXPECT_EQ(role("time", "T"), AxisRole::other);
    EXPECT_EQ(role("Easting"), AxisRole::easting);
    EXPECT_EQ(role("lon"), AxisRole::easting);
    EXPECT_EQ(role("northing"), AxisRole::northing);
    EXPECT_EQ(role("latitude"), AxisRole::northing);
    EXPECT_EQ(role("depth"), AxisRole::vertical);
    EXPECT_EQ(role("z"), AxisRole::vertical);
    EXPECT_EQ(role("band"), AxisRole::other);
    AxisClues depth;
    depth.name = "depth";
    EXPECT_TRUE(positive_down(depth));
    depth.positive = "up";
    EXPECT_FALSE(positive_down(depth));
    AxisClues z;
    z.name = "z";
    EXPECT_FALSE(positive_down(z));
    z.positive = "DOWN";
    EXPECT_TRUE(positive_down(z));
}

TEST(GridAxes, RegularAxisEdgesEitherOrder)
{
    const RegularAxis up = regular_axis({150, 250, 350}, false, "x");
    EXPECT_TRUE(up.ascending);
    EXPECT_EQ(up.low_edge, 100);
    EXPECT_EQ(up.high_edge, 400);
    EXPECT_EQ(up.resolution, 100);
    const RegularAxis down = regular_axis({350, 250, 150}, false, "x");
    EXPECT_FALSE(down.ascending);
    EXPECT_EQ(down.low_edge, 100);
    EXPECT_EQ(down.high_edge, 400);
    // depths 0.25, 0.75 down are elevations -0.25, -0.75: index 0 on top
    const RegularAxis depths = regular_axis({0.25, 0.75, 1.25}, true, "z");
    EXPECT_FALSE(depths.ascending);
    EXPECT_DOUBLE_EQ(depths.high_edge, 0);
    EXPECT_DOUBLE_EQ(depths.low_edge, -1.5);
    EXPECT_EQ(depths.size, 3u);
}

TEST(GridAxes, BadCoordinatesSayWhat)
{
    EXPECT_NE(error_of({}).find("length 0"), std::string::npos);
    EXPECT_NE(error_of({5}).find("single value"), std::string::npos);
    EXPECT_NE(error_of({1, 1, 1}).find("do not change"), std::string::npos);
    EXPECT_NE(error_of({0, 100, 200, 400, 300, 500}).find("not monotonic"),
              std::string::npos)
        << error_of({0, 100, 200, 400, 300, 500});
    EXPECT_NE(error_of({0, 100, 230, 300}).find("not evenly spaced"),
              std::string::npos);
    EXPECT_NE(error_of({0, NAN, 200}).find("not a number"), std::string::npos);
    // float32 centres of a 0.5 m axis are regular within the tolerance
    std::vector<double> z;
    for (int k = 0; k < 313; ++k)
        z.push_back(double(float(-49.75 + 0.5 * k)));
    EXPECT_EQ(error_of(z), "");
}

TEST(MissingValues, FillMissingAndValidRange)
{
    MissingValues m;
    m.exact = {-127, 9999};
    m.valid_min = 0;
    m.valid_max = 20;
    EXPECT_TRUE(m.is_missing(-127));
    EXPECT_TRUE(m.is_missing(NAN));
    EXPECT_TRUE(m.is_missing(21));
    EXPECT_TRUE(m.is_missing(-1));
    EXPECT_FALSE(m.is_missing(0));
    EXPECT_FALSE(m.is_missing(20));
}

TEST(ColumnStackBuilder, SameModelAsTheSliceBuilder)
{
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const auto v = sbrt_test::random_voxels(seed, 3 + seed % 5, 2 + seed % 4,
                                                1 + int(seed * 7 % 29));
        const Model by_slices = sbrt_test::build_model(v);
        ColumnStackBuilder builder(v.frame);
        std::vector<int32_t> column(v.frame.depths);
        for (uint64_t c = 0; c < v.frame.cells(); ++c) {
            for (int z = 0; z < v.frame.depths; ++z)
                column[z] = v.classes[z * v.frame.cells() + c];
            builder.add_column(column.data());
        }
        const Model by_columns = builder.finish();
        by_columns.validate();
        // materials are numbered as met (cell by cell here, slice by slice
        // there): the same voxels and the same runs
        EXPECT_EQ(by_columns.intervals().size(), by_slices.intervals().size());
        for (uint64_t c = 0; c < v.frame.cells(); ++c)
            ASSERT_EQ(by_columns.stack_size(c), by_slices.stack_size(c)) << "cell " << c;
        VoxelExpander expander(by_columns, v.frame);
        std::vector<int32_t> slice(v.frame.cells());
        for (int z = 0; z < v.frame.depths; ++z) {
            expander.next_slice(slice.data());
            for (uint64_t c = 0; c < v.frame.cells(); ++c)
                ASSERT_EQ(slice[c], v.classes[z * v.frame.cells() + c])
                    << "seed " << seed << " cell " << c << " depth " << z;
        }
    }
}

TEST(ColumnStackBuilder, CountsColumns)
{
    Frame f;
    f.rows = 1;
    f.cols = 2;
    f.depths = 2;
    ColumnStackBuilder builder(f);
    const int32_t column[2] = {3, NULL_CLASS};
    builder.add_column(column);
    EXPECT_THROW(builder.finish(), Error);
    builder.add_column(column);
    EXPECT_THROW(builder.add_column(column), Error);
    const Model m = builder.finish();
    EXPECT_EQ(m.intervals().size(), 2u); // the air above is not stored
}

TEST(ColumnStackBuilder, RunsMergeAndMustRise)
{
    Frame f;
    f.rows = 1;
    f.cols = 2;
    f.depths = 6;
    ColumnStackBuilder builder(f);
    // two raw values of one class, a cave, then air: 2 intervals stored
    const ColumnStackBuilder::ClassRun runs[] = {
        {4, 2}, {4, 3}, {NULL_CLASS, 4}, {7, 5}, {NULL_CLASS, 6}};
    builder.add_runs(runs, 5);
    const ColumnStackBuilder::ClassRun falling[] = {{4, 3}, {5, 3}, {6, 6}};
    EXPECT_THROW(builder.add_runs(falling, 3), Error);
    const ColumnStackBuilder::ClassRun short_of_top[] = {{4, 5}};
    EXPECT_THROW(builder.add_runs(short_of_top, 1), Error);
    const ColumnStackBuilder::ClassRun whole[] = {{9, 6}};
    builder.add_runs(whole, 1);
    const Model m = builder.finish();
    m.validate();
    ASSERT_EQ(m.intervals().size(), 4u);
    EXPECT_EQ(m.stack_size(0), 3u); // 4 up to 3, EMPTY to 4, 7 to 5
    EXPECT_EQ(m.intervals()[0].top, 3.0f);
    EXPECT_EQ(m.intervals()[1].material, EMPTY);
    EXPECT_EQ(m.intervals()[2].top, 5.0f);
    EXPECT_EQ(m.intervals()[3].top, 6.0f);
}
