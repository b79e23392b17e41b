/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   CF flag_values and flag_meanings -> labels; counts that do
 *            not pair are refused, not mislabelled (issue 28, item 9)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <string>

#include <gtest/gtest.h>

#include "builders/flag_legend.hpp"
#include "util/error.hpp"

using namespace sbrt;

TEST(FlagLegend, PairsValuesWithWords)
{
    const auto labels = flag_legend({1, 2, 5}, "  anthropogenic peat  fine_sand ");
    ASSERT_EQ(labels.size(), 3u);
    EXPECT_EQ(labels[0].id, 1);
    EXPECT_EQ(labels[0].label, "anthropogenic");
    EXPECT_EQ(labels[2].id, 5);
    EXPECT_EQ(labels[2].label, "fine sand");
    EXPECT_TRUE(flag_legend({}, "").empty());
}

TEST(FlagLegend, Issue28CountsThatDoNotPairNameBoth)
{
    try {
        flag_legend({1, 2, 3}, "a b c d e f g h");
        FAIL() << "no error";
    }
    catch (const Error &e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("flag_values has 3 values and flag_meanings 8 words"),
                  std::string::npos)
            << m;
    }
    EXPECT_THROW(flag_legend({1, 2}, "one"), Error);
    EXPECT_THROW(flag_legend({}, "orphan"), Error);
    EXPECT_THROW(flag_legend({1}, ""), Error);
}

TEST(FlagLegend, ValuesMustBeClasses)
{
    EXPECT_THROW(flag_legend({1.5}, "half"), Error);
    EXPECT_THROW(flag_legend({1e12}, "huge"), Error);
    EXPECT_THROW(flag_legend({-1e12}, "tiny"), Error);
    EXPECT_EQ(flag_legend({-3}, "minus")[0].id, -3);
}
