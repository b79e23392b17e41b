/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A colour ramp for values: colour rules as GRASS keeps them
 *            (pairs of value and colour, linear between), GRASS-free
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLOR_RAMP_HPP
#define SBRT_COLOR_RAMP_HPP

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace sbrt {

/// \brief Rules `low -> high`: a value in [low.value, high.value] takes the
/// colour linearly between theirs; below the first rule the first colour,
/// above the last the last (as r.colors' tables do at their ends).
class ColorRamp {
public:
    struct Stop {
        double value;
        std::array<uint8_t, 3> rgb;
    };
    struct Rule {
        Stop low, high;
    };

    ColorRamp() = default;
    /// Rules in any order; throws sbrt::Error where there are none or a
    /// value is not finite.
    explicit ColorRamp(std::vector<Rule> rules);
    /// A ramp through `stops` evenly from `low` to `high`.
    static ColorRamp through(const std::vector<std::array<uint8_t, 3>> &stops, double low,
                             double high);

    /// The colour (0..255) of `value`.
    glm::dvec3 at(double value) const;
    /// The colour rounded to bytes.
    std::array<uint8_t, 3> rgb_at(double value) const;
    /// The lowest and highest value the rules name.
    double low() const;
    double high() const;
    const std::vector<Rule> &rules() const { return rules_; }
    /// Whether each rule ends at or below the next one's start.
    bool disjoint() const { return disjoint_; }

private:
    std::vector<Rule> rules_; ///< by low value
    /// Whether each rule ends at or below the next one's start (GRASS's
    /// tables, rules files in order): at() then finds its rule by bisection
    bool disjoint_ = false;
};

} // namespace sbrt

#endif
