/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Classification of cell values
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/classifier.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt {

namespace {

bool is_valid_class(double v)
{
    return std::floor(v) == v && v > double(NULL_CLASS) &&
           v <= double(INT32_MAX);
}

/// "*" stands for an open end: -inf as a low bound, +inf as a high one.
double parse_number(const std::string &text, const std::string &where,
                    double open_end = NAN)
{
    if (text == "*" && !std::isnan(open_end))
        return open_end;
    if (text == "-inf")
        return -INFINITY;
    if (text == "inf")
        return INFINITY;
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || std::isnan(v))
        fail(where, ": '", text, "' is not a number");
    return v;
}

} // namespace

Classifier::Classifier(std::vector<ClassRule> rules) : rules_(std::move(rules))
{
}

Classifier Classifier::parse(std::istream &in, const std::string &source)
{
    std::vector<ClassRule> rules;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = source + " line " + std::to_string(number);
        const auto start = line.find_first_not_of(" \t\r");
        if (start == std::string::npos || line[start] == '#')
            continue;
        line = line.substr(start, line.find_last_not_of(" \t\r") - start + 1);
        if (line == "end")
            break;
        std::vector<std::string> fields;
        std::stringstream split(line);
        for (std::string f; std::getline(split, f, ':');)
            fields.push_back(f);
        if (fields.size() < 3)
            fail(where, ": expected low:high:class[:label], got '", line, "'");
        ClassRule rule;
        rule.low = parse_number(fields[0], where, -INFINITY);
        rule.high = parse_number(fields[1], where, INFINITY);
        const double id = parse_number(fields[2], where);
        if (!is_valid_class(id))
            fail(where, ": class '", fields[2],
                 "' is not an integer in the 32-bit range");
        if (rule.low > rule.high)
            fail(where, ": range ", rule.low, ":", rule.high, " is reversed");
        rule.id = int32_t(id);
        for (size_t i = 3; i < fields.size(); ++i)
            rule.label += (i > 3 ? ":" : "") + fields[i];
        rule.label = valid_utf8(rule.label); // a label is text, whatever the file
        rules.push_back(rule);
    }
    if (rules.empty())
        fail(source, ": no classification rules found");
    return Classifier(std::move(rules));
}

int32_t Classifier::integer_class(double value) const
{
    if (!is_valid_class(value))
        fail("value ", value,
             std::floor(value) == value
                 ? " is outside the supported class range (32-bit integers)"
                 : " is not an integer class",
             "; map values to classes with rules= (lines low:high:class)");
    return int32_t(value);
}

int32_t Classifier::ruled_class(double value)
{
    for (const ClassRule &rule : rules_)
        if (value >= rule.low && value <= rule.high)
            return rule.id;
    ++unmatched_;
    return NULL_CLASS;
}

} // namespace sbrt
