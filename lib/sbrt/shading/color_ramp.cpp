/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A colour ramp for values
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/color_ramp.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

ColorRamp::ColorRamp(std::vector<Rule> rules) : rules_(std::move(rules))
{
    if (rules_.empty())
        fail("a colour ramp without rules");
    for (Rule &r : rules_) {
        if (!std::isfinite(r.low.value) || !std::isfinite(r.high.value))
            fail("a colour rule with a value that is not finite");
        if (r.low.value > r.high.value)
            std::swap(r.low, r.high);
    }
    std::stable_sort(rules_.begin(), rules_.end(), [](const Rule &a, const Rule &b) {
        return a.low.value < b.low.value;
    });
    disjoint_ = true;
    for (size_t i = 0; i + 1 < rules_.size(); ++i)
        disjoint_ = disjoint_ && rules_[i].high.value <= rules_[i + 1].low.value;
}

ColorRamp ColorRamp::through(const std::vector<std::array<uint8_t, 3>> &stops, double low,
                             double high)
{
    if (stops.size() < 2)
        fail("a colour ramp needs two colours or more");
    std::vector<Rule> rules;
    for (size_t i = 0; i + 1 < stops.size(); ++i) {
        const double a = low + (high - low) * double(i) / double(stops.size() - 1);
        const double b = low + (high - low) * double(i + 1) / double(stops.size() - 1);
        rules.push_back({{a, stops[i]}, {b, stops[i + 1]}});
    }
    return ColorRamp(std::move(rules));
}

double ColorRamp::low() const { return rules_.front().low.value; }

double ColorRamp::high() const
{
    double high = rules_.front().high.value;
    for (const Rule &r : rules_)
        high = std::max(high, r.high.value);
    return high;
}

glm::dvec3 ColorRamp::at(double value) const
{
    auto color = [](const Stop &s) { return glm::dvec3(s.rgb[0], s.rgb[1], s.rgb[2]); };
    if (!(value > rules_.front().low.value)) // below, at the first, or NaN
        return color(rules_.front().low);
    if (disjoint_) {
        // the last rule starting at or below the value: it holds the value,
        // or the value lies after it, before the next one (or above all)
        const auto next = std::upper_bound(
            rules_.begin(), rules_.end(), value,
            [](double v, const Rule &r) { return v < r.low.value; });
        const Rule &r = *(next - 1);
        if (value > r.high.value)
            return color(r.high);
        const double span = r.high.value - r.low.value;
        const double f = span > 0 ? (value - r.low.value) / span : 0;
        return color(r.low) + f * (color(r.high) - color(r.low));
    }
    // the last rule that starts at or below the value and holds it
    for (size_t i = rules_.size(); i-- > 0;) {
        const Rule &r = rules_[i];
        if (value < r.low.value || value > r.high.value)
            continue;
        const double span = r.high.value - r.low.value;
        const double f = span > 0 ? (value - r.low.value) / span : 0;
        return color(r.low) + f * (color(r.high) - color(r.low));
    }
    // between rules or above all: the colour of the nearest rule end below
    const Rule *best = &rules_.front();
    for (const Rule &r : rules_)
        if (r.high.value <= value && r.high.value >= best->high.value)
            best = &r;
    return color(best->high);
}

std::array<uint8_t, 3> ColorRamp::rgb_at(double value) const
{
    const glm::dvec3 c = at(value);
    return {uint8_t(std::lround(std::clamp(c.x, 0.0, 255.0))),
            uint8_t(std::lround(std::clamp(c.y, 0.0, 255.0))),
            uint8_t(std::lround(std::clamp(c.z, 0.0, 255.0)))};
}

} // namespace sbrt
