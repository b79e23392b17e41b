/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Horizons -> SBRT: crossing horizons, absent units, bottom
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <gtest/gtest.h>

#include "util/error.hpp"
#include "builders/horizon_builder.hpp"

using namespace sbrt;

namespace {

Frame column_frame()
{
    Frame f;
    f.rows = 1;
    f.cols = 1;
    f.depths = 100;
    f.bottom = 0;
    f.top = 100; // tb_res 1: local height == elevation
    return f;
}

std::vector<Material> units(std::vector<int32_t> ids)
{
    std::vector<Material> out;
    for (int32_t id : ids) {
        Material m;
        m.id = id;
        out.push_back(m);
    }
    return out;
}

Model one_column(std::vector<double> tops, double bottom, std::vector<int32_t> ids)
{
    HorizonStackBuilder b(column_frame(), units(ids));
    std::vector<const double *> rows;
    for (const double &t : tops)
        rows.push_back(&t);
    b.add_row(rows, &bottom);
    return b.finish();
}

} // namespace

TEST(Horizons, LayerCakeKeepsContinuousHeights)
{
    const Model m = one_column({80.25, 50.5, 20.125}, 5.0, {1, 2, 3});
    ASSERT_EQ(m.intervals().size(), 4u);
    EXPECT_EQ(m.intervals()[0].material, EMPTY);
    EXPECT_FLOAT_EQ(m.intervals()[0].top, 5.0f);
    EXPECT_EQ(m.materials()[m.intervals()[1].material].id, 3);
    EXPECT_FLOAT_EQ(m.intervals()[1].top, 20.125f);
    EXPECT_EQ(m.materials()[m.intervals()[3].material].id, 1);
    EXPECT_FLOAT_EQ(m.intervals()[3].top, 80.25f);
    m.validate();
}

TEST(Horizons, CrossingHorizonGivesZeroThickness)
{
    // unit 2's top (60) lies below unit 3's top (70): unit 2 vanishes and
    // unit 3 is cut at unit 2's top
    const Model m = one_column({90, 60, 70}, NAN, {1, 2, 3});
    ASSERT_EQ(m.intervals().size(), 2u);
    EXPECT_EQ(m.materials()[m.intervals()[0].material].id, 3);
    EXPECT_FLOAT_EQ(m.intervals()[0].top, 60.0f);
    EXPECT_EQ(m.materials()[m.intervals()[1].material].id, 1);
}

TEST(Horizons, NullHorizonMeansAbsentUnit)
{
    const Model m = one_column({90, NAN, 30}, NAN, {1, 2, 3});
    ASSERT_EQ(m.intervals().size(), 2u);
    EXPECT_EQ(m.materials()[m.intervals()[0].material].id, 3);
    EXPECT_EQ(m.materials()[m.intervals()[1].material].id, 1);
    EXPECT_FLOAT_EQ(m.intervals()[1].top, 90.0f);
}

TEST(Horizons, BottomAboveAllUnitsLeavesEmptyStack)
{
    const Model m = one_column({40, 30}, 50, {1, 2});
    EXPECT_EQ(m.intervals().size(), 0u);
}

TEST(Horizons, ThinLayerSurvives)
{
    const Model m = one_column({50.0001, 50.0}, NAN, {1, 2});
    ASSERT_EQ(m.intervals().size(), 2u);
    EXPECT_GT(m.intervals()[1].top, m.intervals()[0].top);
}

TEST(Horizons, SameIdOnAdjacentUnitsMerges)
{
    const Model m = one_column({90, 60, 30}, NAN, {4, 4, 2});
    ASSERT_EQ(m.intervals().size(), 2u);
    EXPECT_FLOAT_EQ(m.intervals()[1].top, 90.0f);
}

TEST(Horizons, OutOfFrameHeightsAreClampedAndCounted)
{
    HorizonStackBuilder b(column_frame(), units({1}));
    const double top = 150, bottom = -10;
    b.add_row({&top}, &bottom);
    const Model m = b.finish();
    EXPECT_EQ(b.clamped(), 2u);
    ASSERT_EQ(m.intervals().size(), 1u);
    EXPECT_FLOAT_EQ(m.intervals()[0].top, 100.0f);
}

TEST(Horizons, MissingRowsAreAnError)
{
    Frame f = column_frame();
    f.rows = 2;
    HorizonStackBuilder b(f, units({1}));
    const double top = 10;
    b.add_row({&top}, nullptr);
    EXPECT_THROW(b.finish(), Error);
}
