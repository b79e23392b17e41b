/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   CF attributes that change a variable's numbers, checked
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/cf_attributes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt {

namespace {

// key, meaning, counts, NaN allowed, 0 allowed
const AttributeRule RULES[] = {
    {"scale_factor", "the factor stored values are multiplied by", 1, 1, false, false},
    {"add_offset", "what is added to the stored values times scale_factor", 1, 1, false,
     true},
    {"_FillValue", "the stored value that marks no data", 1, 1, true, true},
    {"missing_value", "the stored values that mark no data", 1, 64, true, true},
    {"valid_range", "the lowest and highest valid stored value", 2, 2, false, true},
    {"valid_min", "the lowest valid stored value", 1, 1, false, true},
    {"valid_max", "the highest valid stored value", 1, 1, false, true},
};

std::string number_text(double v)
{
    if (std::isnan(v))
        return "NaN";
    if (std::isinf(v))
        return v > 0 ? "Infinity" : "-Infinity";
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

/// What is wrong with the attribute, or "" when nothing is.
std::string fault_of(const FileAttribute &a, const AttributeRule &rule)
{
    if (!a.numeric)
        return a.text.empty() ? "not a number"
                              : "text ('" + fit_bytes(printable(a.text), 40) +
                                    "'), not a number";
    const size_t n = a.values.size();
    if (n < rule.min_count || n > rule.max_count) {
        std::string list;
        for (size_t i = 0; i < std::min<size_t>(n, 4); ++i)
            list += (i ? ", " : "") + number_text(a.values[i]);
        return std::to_string(n) + " value" + (n == 1 ? "" : "s") +
               (n ? " (" + list + (n > 4 ? ", ..." : "") + ")" : "");
    }
    for (double v : a.values) {
        if (std::isnan(v) && !rule.nan_allowed)
            return "NaN";
        if (std::isinf(v))
            return number_text(v);
        if (v == 0 && !rule.zero_allowed)
            return "0 (every value would become the offset)";
    }
    return "";
}

std::string demand_of(const AttributeRule &rule)
{
    std::string count = rule.min_count == rule.max_count
                            ? (rule.min_count == 1 ? std::string("one")
                                                   : std::to_string(rule.min_count))
                            : "one or more";
    return count + " finite number" + (rule.max_count == 1 ? "" : "s") +
           (rule.zero_allowed ? "" : " other than 0") +
           (rule.nan_allowed ? " (or NaN)" : "") + ", " + rule.meaning;
}

bool says(const std::string &text, const char *word)
{
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return lower.find(word) != std::string::npos;
}

} // namespace

const AttributeRule &attribute_rule(const std::string &key)
{
    for (const AttributeRule &rule : RULES)
        if (key == rule.key)
            return rule;
    fail("attribute_rule: no rule for '", key, "'");
}

std::vector<double> checked_numbers(const FileAttribute &attribute,
                                    const AttributeRule &rule, const std::string &where,
                                    const std::string &variable, const std::string &file)
{
    if (!attribute.present)
        return {};
    const std::string fault = fault_of(attribute, rule);
    if (!fault.empty())
        fail(where, ": attribute ", rule.key, " is ", fault, "; it must be ",
             demand_of(rule), ". Mend it (e.g. ncatted -O -a ", rule.key, ",", variable,
             ",o,d,<value> ", file, ") or delete it (ncatted -O -a ", rule.key, ",",
             variable, ",d,, ", file, ")");
    return attribute.values;
}

std::string probability_hint(const std::string &name, const std::string &long_name,
                             const std::string &units, size_t classes)
{
    std::string why;
    if (units == "%" || says(units, "percent"))
        why = "units " + units;
    else
        for (const char *word : {"prob", "kans", "likelihood", "chance"})
            if (says(name, word) || says(long_name, word)) {
                why = std::string("its ") + (says(name, word) ? "name" : "long_name") +
                      " says '" + word + "'";
                break;
            }
    if (why.empty())
        return "";
    return std::to_string(classes) + " distinct value" + (classes == 1 ? "" : "s") +
           ", " + why;
}

} // namespace sbrt
