/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Classes named by id, alias (a survey's code or short name)
 *            or label (issue 51, item 3): alias: lines of presets, the
 *            embedded GeoTOP aliases, the resolver of list options, a
 *            label with commas, the error listing the names by id
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/class_names.hpp"
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

SurveyPreset preset_of(const std::string &text)
{
    std::istringstream in("name: t\nreference: test\n" + text);
    return parse_preset(in, "t.rules");
}

Material material(int32_t id, const std::string &label)
{
    Material m;
    m.id = id;
    m.label = label;
    return m;
}

const std::string LOAM = "clayey sand, sandy clay, loam (kleiig zand, zandige klei en leem)";

/// GeoTOP lithoclasses as an import meets them: 3, 6, 2, 7, 8, 5, 0, 1;
/// class 9 relabelled by the user.
std::vector<Material> geotop_materials()
{
    return {Material{},
            material(3, LOAM),
            material(6, "medium sand (zand midden)"),
            material(2, "clay (klei)"),
            material(7, "coarse sand (zand grof)"),
            material(8, "gravel (grind)"),
            material(5, "fine sand (zand fijn)"),
            material(0, "anthropogenic (antropogeen)"),
            material(1, "organic, peat (organisch materiaal, veen)"),
            material(9, "my shells")};
}

} // namespace

TEST(ClassAliases, AliasLinesAreParsed)
{
    const SurveyPreset p = preset_of("1 1:2:3 clay (klei)\n2 4:5:6 sand\n"
                                     "alias: 1 k, clay\nalias: 2  z \n");
    ASSERT_EQ(p.aliases.size(), 3u);
    EXPECT_EQ(p.aliases[0].id, 1);
    EXPECT_EQ(p.aliases[0].name, "k");
    EXPECT_EQ(p.aliases[1].name, "clay");
    EXPECT_EQ(p.aliases[2].id, 2);
    EXPECT_EQ(p.aliases[2].name, "z");
    // older presets, without alias: lines, read as before
    EXPECT_TRUE(preset_of("1 1:2:3 clay\n").aliases.empty());
}

TEST(ClassAliases, BadAliasLinesAreRefused)
{
    const auto error = [](const std::string &text) {
        return error_of([&] { preset_of("1 1:2:3 clay\n2 4:5:6 sand\n" + text); });
    };
    EXPECT_NE(error("alias: k\n").find("t.rules line 5: expected alias: ID NAME"),
              std::string::npos);
    EXPECT_NE(error("alias: 1 k,,c\n").find("line 5: alias ''"), std::string::npos);
    EXPECT_NE(error("alias: 1 12\n").find("not a number"), std::string::npos);
    EXPECT_NE(error("alias: 1 " + std::string(65, 'x') + "\n").find("1 to 64"),
              std::string::npos);
    EXPECT_NE(error("alias: 1 a\x1b[2Jb\n").find("printable"), std::string::npos);
    EXPECT_NE(error("alias: 3 k\n").find("names class 3, which has no class line"),
              std::string::npos);
    EXPECT_NE(error("alias: 1 k\nalias: 2 K\n").find("names both class 1 and class 2"),
              std::string::npos);
    EXPECT_NE(error("alias: 1 sand\n").find("is the label of class 2"), std::string::npos);
}

TEST(ClassAliases, GeotopPresetsCarryTnoCodes)
{
    const SurveyPreset &litho = find_preset("geotop_lithoclass");
    const auto names_of = [&](const SurveyPreset &p, int32_t id) {
        std::string out;
        for (const ClassAlias &a : p.aliases)
            if (a.id == id)
                out += (out.empty() ? "" : ",") + a.name;
        return out;
    };
    EXPECT_EQ(names_of(litho, 0), "a,anthropogenic");
    EXPECT_EQ(names_of(litho, 2), "k,clay");
    EXPECT_EQ(names_of(litho, 3), "kz,loam,clayey sand,sandy clay");
    EXPECT_EQ(names_of(litho, 5), "zf,fine sand");
    EXPECT_EQ(names_of(litho, 8), "g,gravel");
    EXPECT_EQ(names_of(litho, 9), "she,shells");
    const SurveyPreset &strat = find_preset("geotop_strat");
    EXPECT_EQ(names_of(strat, 3100), "BX");
    EXPECT_EQ(names_of(strat, 1000), "AAOP");
    // every unit has its code
    for (const ClassStyle &s : strat.classes)
        EXPECT_EQ(names_of(strat, s.low), s.label.substr(0, s.label.find(' ')));
}

TEST(ClassNames, IdAliasLabelAndLabelWithoutCommas)
{
    const ClassNames names(geotop_materials());
    EXPECT_EQ(names.find("8"), 5u);
    EXPECT_EQ(names.find("gravel"), 5u);
    EXPECT_EQ(names.find("g"), 5u);
    EXPECT_EQ(names.find(" G "), 5u);
    EXPECT_EQ(names.find("zf"), 6u);
    EXPECT_EQ(names.find("Fine Sand"), 6u);
    EXPECT_EQ(names.find("kz"), 1u);
    EXPECT_EQ(names.find("loam"), 1u);
    EXPECT_EQ(names.find("0"), 7u);
    EXPECT_EQ(names.find("a"), 7u);
    EXPECT_EQ(names.find("gravel (grind)"), 5u);
    EXPECT_EQ(names.find(LOAM), 1u);
    EXPECT_EQ(names.find("clayey sand sandy clay loam (kleiig zand zandige klei en leem)"), 1u);
    EXPECT_EQ(names.find("organic peat (organisch materiaal veen)"), 8u);
    // a relabelled class lends no preset aliases: "she" names nothing
    EXPECT_EQ(names.find("my shells"), 9u);
    EXPECT_EQ(names.find("she"), EMPTY);
    EXPECT_TRUE(names.aliases(9).empty());
    EXPECT_EQ(names.find("4"), EMPTY);
    EXPECT_EQ(names.find(""), EMPTY);
    EXPECT_EQ(names.find("sand"), EMPTY);
}

TEST(ClassNames, ALabelPartedAtItsCommasIsJoinedAgain)
{
    const ClassNames names(geotop_materials());
    // as G_parser parts classes=gravel,clayey sand, sandy clay, ...,zf
    const std::vector<std::string> parts = {"gravel",        "clayey sand",
                                            " sandy clay",   " loam (kleiig zand",
                                            " zandige klei en leem)", "zf"};
    EXPECT_EQ(names.resolve(parts, "classes"), (std::vector<uint32_t>{5, 1, 6}));
    EXPECT_EQ(names.resolve({"organic", " peat (organisch materiaal", " veen)"}, "hide"),
              (std::vector<uint32_t>{8}));
    // short names of the same class still resolve one by one
    EXPECT_EQ(names.resolve({"clayey sand", "sandy clay"}, "classes"),
              (std::vector<uint32_t>{1, 1}));
}

TEST(ClassNames, AnUnknownNameListsTheNamesSortedById)
{
    const ClassNames names(geotop_materials());
    const std::string e = error_of([&] { names.resolve({"g", "granite"}, "hide", "SBRT <gt>"); });
    EXPECT_NE(e.find("hide: no class of SBRT <gt> is named 'granite' (an id, code, short "
                     "name or label"),
              std::string::npos)
        << e;
    EXPECT_NE(e.find("without its commas"), std::string::npos);
    const std::string listed =
        "0 (anthropogenic (antropogeen); also a, anthropogenic), 1 (organic, peat "
        "(organisch materiaal, veen); also v, peat, organic), 2 (clay (klei); also k, "
        "clay), 3 (" + LOAM + "; also kz, loam, clayey sand, sandy clay), 5 (fine sand "
        "(zand fijn); also zf, fine sand), 6 (medium sand (zand midden); also zm, medium "
        "sand), 7 (coarse sand (zand grof); also zg, coarse sand), 8 (gravel (grind); "
        "also g, gravel), 9 (my shells)";
    EXPECT_NE(e.find(listed), std::string::npos) << e;
    EXPECT_EQ(names.accepted(), listed);
}

TEST(ClassNames, HostileLabelsAndLongListsStayReadable)
{
    std::vector<Material> materials = {Material{}, material(2, "x\x1b[2Jy"), material(1, "")};
    for (int32_t id = 10; id < 3000; ++id)
        materials.push_back(material(id, std::string(100, 'l')));
    const ClassNames names(materials);
    const std::string list = names.accepted();
    EXPECT_EQ(list.find('\x1b'), std::string::npos);
    EXPECT_EQ(list.rfind("1, 2 (x", 0), 0u) << list.substr(0, 40);
    EXPECT_LT(list.size(), 17000u);
    EXPECT_NE(list.find("more (r3.sbrt.convert -p"), std::string::npos);
    const std::string e = error_of([&] { names.resolve_one(std::string(5000, 'q'), "hide"); });
    EXPECT_LT(e.size(), 17500u);
}

TEST(ClassNames, AliasesFromTheGivenPresets)
{
    const SurveyPreset p = preset_of("7 1:2:3 Boxtel\nalias: 7 BX, boxtel formation\n");
    const ClassNames names({Material{}, material(7, "boxtel")}, {p});
    EXPECT_EQ(names.find("bx"), 1u);
    EXPECT_EQ(names.find("Boxtel Formation"), 1u);
    const ClassNames unlabelled({Material{}, material(7, "")}, {p});
    EXPECT_EQ(unlabelled.find("BX"), EMPTY);
}

TEST(ClassNames, LongListsAndManyCommasStayCheap)
{
    std::string many = "a";
    for (int i = 0; i < 40; ++i)
        many += ", a";
    std::vector<Material> materials = {Material{}, material(1, many)};
    for (int32_t id = 2; id < 20000; ++id)
        materials.push_back(material(id, "class " + std::to_string(id)));
    const ClassNames names(materials);
    // 20000 answers against 20000 classes: hash look-ups, a bounded join
    const std::vector<std::string> list(20000, "class 19999");
    EXPECT_EQ(names.resolve(list, "classes").size(), 20000u);
    // past 32 commas a label is named without them
    EXPECT_EQ(names.find(std::string(41, 'a')), EMPTY);
    std::string bare = "a";
    for (int i = 0; i < 40; ++i)
        bare += " a";
    EXPECT_EQ(names.find(bare), 1u);
}
