/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Values -> classes: integers, rules, clear errors
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "builders/classifier.hpp"
#include "util/error.hpp"

using namespace sbrt;

TEST(Classifier, IntegersPassThrough)
{
    Classifier c;
    EXPECT_EQ(c.classify(7.0), 7);
    EXPECT_EQ(c.classify(-3.0), -3);
    EXPECT_EQ(c.classify(NAN), NULL_CLASS);
}

TEST(Classifier, NonIntegerNamesValueAndRules)
{
    Classifier c;
    try {
        c.classify(2.5);
        FAIL() << "no error";
    }
    catch (const Error &e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("2.5"), std::string::npos) << m;
        EXPECT_NE(m.find("rules="), std::string::npos) << m;
    }
    EXPECT_THROW(c.classify(1e12), Error);
    EXPECT_THROW(c.classify(INFINITY), Error);
}

TEST(Classifier, RulesMapRangesAndCountMisses)
{
    std::istringstream in("# lithology\n0:1.5:1:sand\n1.5:10:2:clay: stiff\n"
                          "\n20:*:3\nend\n99:99:9\n");
    Classifier c = Classifier::parse(in, "rules");
    ASSERT_EQ(c.rules().size(), 3u);
    EXPECT_EQ(c.rules()[1].label, "clay: stiff");
    EXPECT_EQ(c.classify(0.2), 1);
    EXPECT_EQ(c.classify(1.5), 1); // first matching rule wins
    EXPECT_EQ(c.classify(3.7), 2);
    EXPECT_EQ(c.classify(15.0), NULL_CLASS);
    EXPECT_EQ(c.unmatched(), 1u);
}

TEST(Classifier, BadRulesAreReportedWithLine)
{
    std::istringstream in("1:2:3\nfoo:2:3\n");
    try {
        Classifier::parse(in, "r.txt");
        FAIL() << "no error";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("r.txt line 2"), std::string::npos);
    }
    std::istringstream reversed("5:1:2\n");
    EXPECT_THROW(Classifier::parse(reversed, "r"), Error);
    std::istringstream fraction("1:2:2.5\n");
    EXPECT_THROW(Classifier::parse(fraction, "r"), Error);
    std::istringstream empty("# nothing\n");
    EXPECT_THROW(Classifier::parse(empty, "r"), Error);
}
