/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Rules that reach a class and rules that reach none
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "rule_counts.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace {

/// Whether a class id lies in low..high (both included).
bool any_id_in(const std::vector<int32_t> &ids, double low, double high)
{
    const auto it = std::lower_bound(ids.begin(), ids.end(), low,
                                     [](int32_t id, double v) { return id < v; });
    return it != ids.end() && double(*it) <= high;
}

/// Whether a class id lies strictly between low and high.
bool any_id_between(const std::vector<int32_t> &ids, double low, double high)
{
    const auto it = std::upper_bound(ids.begin(), ids.end(), low,
                                     [](double v, int32_t id) { return v < id; });
    return it != ids.end() && double(*it) < high;
}

std::string number_text(double value)
{
    std::ostringstream out;
    out << value;
    return out.str();
}

void count_one(RuleCounts &counts, bool reaches, const std::string &text)
{
    ++counts.lines;
    if (reaches)
        return;
    if (counts.unmatched++ == 0)
        counts.first_unmatched = text;
}

} // namespace

std::vector<int32_t> class_ids(const std::vector<sbrt::Material> &materials)
{
    std::vector<int32_t> ids;
    for (size_t i = 1; i < materials.size(); ++i)
        ids.push_back(materials[i].id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

RuleCounts count_label_rules(const std::vector<sbrt::ClassStyle> &rules,
                             const std::vector<int32_t> &ids)
{
    RuleCounts counts;
    for (const sbrt::ClassStyle &rule : rules)
        count_one(counts, any_id_in(ids, rule.low, rule.high),
                  rule.low == rule.high
                      ? std::to_string(rule.low)
                      : std::to_string(rule.low) + ":" + std::to_string(rule.high));
    return counts;
}

RuleCounts count_color_rules(const std::vector<double> &values,
                             const std::vector<int32_t> &ids)
{
    std::vector<double> sorted;
    for (const double value : values)
        if (std::isfinite(value))
            sorted.push_back(value);
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    RuleCounts counts;
    for (const double value : values) {
        if (!std::isfinite(value)) {
            count_one(counts, false, number_text(value));
            continue;
        }
        const auto at = std::lower_bound(sorted.begin(), sorted.end(), value);
        bool reaches = any_id_in(ids, value, value);
        if (!reaches && at != sorted.begin())
            reaches = any_id_between(ids, *(at - 1), value);
        if (!reaches && at + 1 != sorted.end())
            reaches = any_id_between(ids, value, *(at + 1));
        count_one(counts, reaches, number_text(value));
    }
    return counts;
}
