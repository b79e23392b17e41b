/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Geological profiles (profile/): the line unfolded, the classes
 *            of a section along a bent line against the voxels under each
 *            column's point, the layers' extent, axis ticks, the vertical
 *            datum member
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "format/format.hpp"
#include "util/axis_ticks.hpp"
#include "measure/class_profile.hpp"
#include "measure/profile_line.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

TEST(ProfileLine, UnfoldsABentLineIntoDistances)
{
    const ProfileLine line({{0, 0}, {30, 40}, {30, 40}, {30, 10}});
    ASSERT_EQ(line.vertices().size(), 3u); // the repeated vertex dropped
    EXPECT_DOUBLE_EQ(line.length(), 80);
    EXPECT_EQ(line.vertex_distances(), (std::vector<double>{0, 50, 80}));
    EXPECT_EQ(line.point_at(25), glm::dvec2(15, 20));
    EXPECT_EQ(line.point_at(50), glm::dvec2(30, 40));
    EXPECT_EQ(line.point_at(60), glm::dvec2(30, 30));
    EXPECT_EQ(line.point_at(-5), glm::dvec2(0, 0));
    EXPECT_EQ(line.point_at(99), glm::dvec2(30, 10));
}

TEST(ProfileLine, RefusesLinesWithoutTwoDistinctFinitePoints)
{
    EXPECT_THROW(ProfileLine({{1, 2}}), Error);
    EXPECT_THROW(ProfileLine({{1, 2}, {1, 2}}), Error);
    EXPECT_THROW(ProfileLine({{1, 2}, {NAN, 3}}), Error);
    EXPECT_THROW(ProfileLine({{1, 2}, {INFINITY, 3}}), Error);
}

TEST(ClassProfile, EqualsTheVoxelsUnderEachColumnAlongABentLine)
{
    // random columns with caves and air; UTM-size coordinates
    sbrt_test::Voxels v = sbrt_test::random_voxels(31, 23, 17, 40);
    const double west = 500000, south = 5800000;
    v.frame.west = west;
    v.frame.east = west + 17 * 25.0;
    v.frame.south = south;
    v.frame.north = south + 23 * 25.0;
    const Model model = sbrt_test::build_model(v);
    const Frame &f = model.frame();
    // three vertices, the last beyond the model's east edge
    const ProfileLine line({{west + 10, south + 20}, {west + 300, south + 560}, {west + 500, south + 100}});
    const int cols = 173, rows = 2 * f.depths + 7; // rows off the voxels' own
    const ProfileExtent extent{f.bottom - 3.3, f.top + 5.1};
    const ClassProfile p = class_profile(model, line, cols, rows, extent);
    ASSERT_EQ(p.classes.size(), size_t(cols) * size_t(rows));
    size_t off_model = 0, solid = 0;
    for (int c = 0; c < cols; ++c) {
        const glm::dvec2 at = line.point_at((c + 0.5) * line.length() / cols);
        const int col = int(std::floor((at.x - f.west) / f.ew_res()));
        const int row = int(std::floor((f.north - at.y) / f.ns_res()));
        const bool inside = col >= 0 && col < f.cols && row >= 0 && row < f.rows;
        off_model += !inside;
        for (int r = 0; r < rows; ++r) {
            const double z = extent.top - (r + 0.5) * (extent.top - extent.bottom) / rows;
            EXPECT_DOUBLE_EQ(p.elevation(r), z);
            const int depth = int(std::floor((z - f.bottom) / f.tb_res()));
            int32_t expected = NULL_CLASS;
            if (inside && depth >= 0 && depth < f.depths)
                expected = v.classes[(size_t(depth) * f.rows + row) * f.cols + col];
            solid += expected != NULL_CLASS;
            ASSERT_EQ(p.at(r, c), expected) << "column " << c << " row " << r;
        }
    }
    EXPECT_GT(off_model, 0u);
    EXPECT_GT(solid, size_t(cols) * size_t(rows) / 4);
}

TEST(ClassProfile, SolidExtentIsTheLayersUnderTheLine)
{
    // one column of layers from 3 to 9 voxels, the rest empty but one at 1-2
    sbrt_test::Voxels v;
    v.frame.rows = 1;
    v.frame.cols = 4;
    v.frame.depths = 12;
    v.frame.west = 0;
    v.frame.east = 40;
    v.frame.south = 0;
    v.frame.north = 10;
    v.frame.bottom = 100;
    v.frame.top = 112;
    v.classes.assign(v.frame.voxels(), NULL_CLASS);
    for (int z = 3; z < 9; ++z)
        v.classes[size_t(z) * 4 + 1] = 5;
    v.classes[1 * 4 + 3] = 7;
    const Model model = sbrt_test::build_model(v);
    // the line over columns 0 and 1 only
    const auto near = solid_extent(model, ProfileLine({{1, 5}, {19, 5}}), 10);
    ASSERT_TRUE(near);
    EXPECT_DOUBLE_EQ(near->bottom, 103);
    EXPECT_DOUBLE_EQ(near->top, 109);
    const auto all = solid_extent(model, ProfileLine({{1, 5}, {39, 5}}), 40);
    ASSERT_TRUE(all);
    EXPECT_DOUBLE_EQ(all->bottom, 101);
    EXPECT_DOUBLE_EQ(all->top, 109);
    EXPECT_FALSE(solid_extent(model, ProfileLine({{1, 5}, {9, 5}}), 10));
    EXPECT_FALSE(solid_extent(model, ProfileLine({{100, 5}, {200, 5}}), 10));
    EXPECT_THROW(class_profile(model, ProfileLine({{1, 5}, {9, 5}}), 0, 3, {100, 112}), Error);
    EXPECT_THROW(class_profile(model, ProfileLine({{1, 5}, {9, 5}}), 3, 3, {112, 100}), Error);
    EXPECT_THROW(class_profile(model, ProfileLine({{1, 5}, {9, 5}}), 1 << 15, 1 << 14, {100, 112}),
                 Error);
}

TEST(AxisTicks, StepsOfOneTwoOrFiveTimesAPowerOfTen)
{
    EXPECT_DOUBLE_EQ(tick_step(0, 606, 7), 100);
    EXPECT_DOUBLE_EQ(tick_step(-50, 76, 8), 20);
    EXPECT_DOUBLE_EQ(tick_step(0, 5593, 9), 1000);
    EXPECT_DOUBLE_EQ(tick_step(0, 1, 10), 0.1);
    EXPECT_DOUBLE_EQ(tick_step(0, 1, 4), 0.5);
    EXPECT_DOUBLE_EQ(tick_step(0, 1, 5), 0.2);
    EXPECT_EQ(ticks(-60, 80, 20), (std::vector<double>{-60, -40, -20, 0, 20, 40, 60, 80}));
    EXPECT_EQ(ticks(0.05, 0.31, 0.1), (std::vector<double>{0.1, 0.2, 0.30000000000000004}));
    EXPECT_EQ(ticks(0, 2625, 500).size(), 6u);
    EXPECT_THROW(tick_step(1, 1, 5), Error);
    EXPECT_THROW(ticks(0, 1, 0), Error);
}

TEST(VerticalDatum, TravelsAsOneLineAndRefusesAnythingElse)
{
    Model model = sbrt_test::build_model(sbrt_test::random_voxels(3, 2, 2, 3));
    model.set_vertical_datum("NAP");
    EXPECT_EQ(encode_datum(model), "NAP\n");
    Model read = sbrt_test::build_model(sbrt_test::random_voxels(3, 2, 2, 3));
    decode_datum("NAVD88\r\n", read, "datum");
    EXPECT_EQ(read.vertical_datum(), "NAVD88");
    EXPECT_THROW(decode_datum("NAP\nrm -rf\n", read, "datum"), Error);
    EXPECT_THROW(decode_datum(std::string(MAX_DATUM_CHARS + 1, 'x'), read, "datum"), Error);
    EXPECT_THROW(decode_datum(std::string("N\0P", 3), read, "datum"), Error);
}

TEST(VerticalDatum, IsWrittenAndReadWithTheModelAndKeptByALegendRewrite)
{
    const std::string parent = sbrt_test::temp_dir("datum");
    const std::string dir = parent + "/m";
    Model model = sbrt_test::build_model(sbrt_test::random_voxels(5, 3, 4, 6));
    model.set_vertical_datum("NAP");
    write_sbrt(dir, model, "test\n");
    EXPECT_EQ(read_sbrt(dir).vertical_datum(), "NAP");
    rewrite_legend(dir, model, "support\n");
    EXPECT_EQ(read_sbrt(dir).vertical_datum(), "NAP");
    // a model without one writes no member and reads none
    write_sbrt(dir, sbrt_test::build_model(sbrt_test::random_voxels(5, 3, 4, 6)), "again\n");
    EXPECT_EQ(read_sbrt(dir).vertical_datum(), "");
    std::system(("rm -rf '" + parent + "'").c_str());
}
