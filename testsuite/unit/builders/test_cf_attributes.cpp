/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   CF attributes that change a variable's numbers are checked
 *            before use (issue 48, item 10); the probability hint (item 13)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "builders/cf_attributes.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

FileAttribute numbers(std::vector<double> values)
{
    FileAttribute a;
    a.present = a.numeric = true;
    a.values = std::move(values);
    return a;
}

/// The message checked_numbers throws, or "" when it takes the attribute.
std::string refusal(const FileAttribute &a, const char *key)
{
    try {
        checked_numbers(a, attribute_rule(key), "variable 'kh' of <f.nc>", "kh", "f.nc");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(CfAttributes, SoundValuesAreTaken)
{
    EXPECT_EQ(checked_numbers(numbers({0.01}), attribute_rule("scale_factor"), "w", "kh",
                              "f.nc"),
              std::vector<double>{0.01});
    EXPECT_TRUE(checked_numbers(FileAttribute{}, attribute_rule("scale_factor"), "w",
                                "kh", "f.nc")
                    .empty());
    EXPECT_EQ(refusal(numbers({-3}), "add_offset"), "");
    EXPECT_EQ(refusal(numbers({0}), "add_offset"), "");
    // xarray writes NaN as a float's fill: NaN is never a value anyway
    EXPECT_EQ(refusal(numbers({std::nan("")}), "_FillValue"), "");
    EXPECT_EQ(refusal(numbers({-999, -998}), "missing_value"), "");
    EXPECT_EQ(refusal(numbers({0, 100}), "valid_range"), "");
}

TEST(CfAttributes, Issue48BadValuesNameVariableAndAttribute)
{
    const double inf = std::numeric_limits<double>::infinity();
    FileAttribute text;
    text.present = true;
    text.text = "0.01";
    const struct {
        FileAttribute attribute;
        const char *key, *fault;
    } cases[] = {
        {numbers({std::nan("")}), "scale_factor", "attribute scale_factor is NaN"},
        {numbers({0}), "scale_factor", "attribute scale_factor is 0"},
        {text, "scale_factor", "attribute scale_factor is text ('0.01')"},
        {numbers({0.01, 0.02}), "scale_factor", "is 2 values (0.01, 0.02)"},
        {numbers({}), "scale_factor", "is 0 values"},
        {numbers({inf}), "add_offset", "attribute add_offset is Infinity"},
        {numbers({std::nan("")}), "add_offset", "attribute add_offset is NaN"},
        {numbers({-inf}), "_FillValue", "attribute _FillValue is -Infinity"},
        {numbers({1, 2}), "_FillValue", "attribute _FillValue is 2 values"},
        {numbers({-999, inf}), "missing_value", "attribute missing_value is Infinity"},
        {numbers({5}), "valid_range", "attribute valid_range is 1 value"},
        {numbers({std::nan("")}), "valid_min", "attribute valid_min is NaN"},
    };
    for (const auto &c : cases) {
        const std::string message = refusal(c.attribute, c.key);
        EXPECT_NE(message.find("variable 'kh' of <f.nc>"), std::string::npos) << message;
        EXPECT_NE(message.find(c.fault), std::string::npos) << message;
        EXPECT_NE(message.find(std::string("ncatted -O -a ") + c.key + ",kh,"),
                  std::string::npos)
            << message;
    }
}

TEST(CfAttributes, HostileTextIsShownPrintableAndShort)
{
    FileAttribute text;
    text.present = true;
    text.text = "\x1b[31m" + std::string(500, 'x');
    const std::string message = refusal(text, "add_offset");
    EXPECT_EQ(message.find('\x1b'), std::string::npos);
    EXPECT_LT(message.size(), 400u);
}

TEST(CfAttributes, Issue48ProbabilityHint)
{
    EXPECT_EQ(probability_hint("kans_5", "kans op lithoklasse 5", "%", 86),
              "86 distinct values, units %");
    EXPECT_EQ(probability_hint("p_sand", "Probability of sand", "", 40),
              "40 distinct values, its long_name says 'prob'");
    EXPECT_EQ(probability_hint("kans_1", "", "1", 12),
              "12 distinct values, its name says 'kans'");
    EXPECT_EQ(probability_hint("lithok", "lithoklasse", "", 9), "");
    EXPECT_EQ(probability_hint("strat", "stratigraphic unit", "", 120), "");
}
