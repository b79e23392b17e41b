/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Category rules and survey presets: parsing, bad lines named,
 *            the embedded GeoTOP presets and how a file is identified
 *            (issue 31)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <functional>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "model/legend_rules.hpp"
#include "model/survey_presets.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

std::string error_of(const std::function<void()> &f)
{
    try {
        f();
    }
    catch (const Error &e) {
        return e.what();
    }
    return "no error";
}

using Attributes = std::vector<std::pair<std::string, std::string>>;

} // namespace

TEST(LegendRules, CategoryRulesAsRCategoryReadsThem)
{
    std::istringstream in("# comment\n\n1:peat\n2:3:clay: stiff\n -7 : below\n");
    const auto rules = parse_category_rules(in, "labels.txt");
    ASSERT_EQ(rules.size(), 3u);
    EXPECT_EQ(rules[0].low, 1);
    EXPECT_EQ(rules[0].label, "peat");
    EXPECT_EQ(rules[1].low, 2);
    EXPECT_EQ(rules[1].high, 3);
    EXPECT_EQ(rules[1].label, "clay: stiff");
    EXPECT_EQ(rules[2].low, -7);
    EXPECT_EQ(rules[2].label, "below");
    EXPECT_FALSE(rules[0].has_color);
}

TEST(LegendRules, BadLinesAreNamed)
{
    std::istringstream a("1:ok\npeat 2\n");
    EXPECT_NE(error_of([&] { parse_category_rules(a, "labels.txt"); })
                  .find("labels.txt line 2: expected id:label"),
              std::string::npos);
    // a file that is no rules file (issue 48, item 5): its line is named,
    // never echoed
    std::istringstream shadow("root:$y$j9T$secret:19000:0:99999:7:::\n");
    const std::string shadow_error =
        error_of([&] { parse_category_rules(shadow, "/etc/shadow"); });
    EXPECT_NE(shadow_error.find("/etc/shadow line 1:"), std::string::npos);
    EXPECT_EQ(shadow_error.find("secret"), std::string::npos) << shadow_error;
    std::istringstream passwd("name: x\nreference: y\nroot:x:0:0:root:/root:/bin/bash\n");
    EXPECT_EQ(error_of([&] { parse_preset(passwd, "p"); }).find("/root"), std::string::npos);
    // labels are valid UTF-8 where they enter (item 9)
    std::istringstream bad_utf8("1:zand \xFF grof\n");
    EXPECT_EQ(parse_category_rules(bad_utf8, "l")[0].label, "zand \xEF\xBF\xBD grof");
    std::istringstream b("5:2:backwards\n");
    EXPECT_NE(error_of([&] { parse_category_rules(b, "r"); }).find("runs backwards"),
              std::string::npos);
    std::istringstream c("name: x\nreference: y\n1 10:20:300 too red\n");
    EXPECT_NE(error_of([&] { parse_preset(c, "p.rules"); })
                  .find("p.rules line 3: expected id red:green:blue label"),
              std::string::npos);
    std::istringstream d("name: x\n1 1:2:3 a\n");
    EXPECT_NE(error_of([&] { parse_preset(d, "p.rules"); }).find("reference:"),
              std::string::npos);
    std::istringstream e("nmae: x\n");
    EXPECT_NE(error_of([&] { parse_preset(e, "p.rules"); }).find("unknown key nmae"),
              std::string::npos);
}

TEST(LegendRules, ApplyKeepsOwnOnlyWhenAsked)
{
    std::vector<Material> m(3);
    m[1].id = 1;
    m[1].label = "mine";
    m[2].id = 2;
    ClassStyle s;
    s.low = 1;
    s.high = 2;
    s.label = "theirs";
    s.has_label = true;
    s.red = 9;
    s.has_color = true;
    EXPECT_EQ(apply_styles(m, {s}, true), 2u);
    EXPECT_EQ(m[1].label, "mine");
    EXPECT_EQ(m[2].label, "theirs");
    EXPECT_TRUE(m[1].has_color);
    EXPECT_EQ(apply_styles(m, {s}), 1u);
    EXPECT_EQ(m[1].label, "theirs");
    EXPECT_EQ(m[0].label, ""); // EMPTY untouched
}

TEST(SurveyPresets, GeotopPresetsNameTheirSourceAndClasses)
{
    const SurveyPreset &litho = find_preset("geotop_lithoclass");
    EXPECT_NE(litho.reference.find("REF_GTP_LITHO_CLASS"), std::string::npos);
    ASSERT_EQ(litho.classes.size(), 9u); // 0-9 without the unused 4
    EXPECT_EQ(litho.classes[2].low, 2);
    EXPECT_EQ(litho.classes[2].label, "clay (klei)");
    EXPECT_EQ(litho.classes[2].green, 146);
    const SurveyPreset &strat = find_preset("geotop_strat");
    EXPECT_NE(strat.reference.find("REF_GTP_STR_UNIT"), std::string::npos);
    bool aaop = false, krwy = false;
    for (const ClassStyle &c : strat.classes) {
        aaop = aaop || (c.low == 1000 && c.label.rfind("AAOP ", 0) == 0);
        krwy = krwy || (c.low == 4000 && c.label.rfind("KRWY ", 0) == 0);
    }
    EXPECT_TRUE(aaop);
    EXPECT_TRUE(krwy);
    EXPECT_NE(error_of([] { find_preset("geotop_lithology"); })
                  .find("known: geotop_lithoclass,geotop_strat"),
              std::string::npos);
}

TEST(SurveyPresets, AFileIdentifiesItself)
{
    const Attributes geotop = {{"title", "geotop v01r6 (100.0m * 100.0m * 0.5m"},
                               {"Conventions", "CF-1.4"}};
    const SurveyPreset *p = identify_preset("lithok", geotop);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->name, "geotop_lithoclass");
    p = identify_preset("strat", {{"institution", "TNO / Geologische Dienst Nederland"}});
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(p->name, "geotop_strat");
    EXPECT_NE(identify_preset("strat", {{"source", "Generated by nl.tno.dino.geo3dmodel."
                                                   "generator.GeoTOPVoxelModelGenerator"}}),
              nullptr);
    EXPECT_EQ(identify_preset("kans_1", geotop), nullptr);          // not a class variable
    EXPECT_EQ(identify_preset("lithok", {{"title", "REGIS II"}}), nullptr); // another survey
}
