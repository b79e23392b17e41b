/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Axis roles from CF clues; regular axes from cell centres
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/grid_axes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

namespace {

std::string lower(std::string s)
{
    for (char &c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool one_of(const std::string &s, std::initializer_list<const char *> names)
{
    return std::any_of(names.begin(), names.end(),
                       [&](const char *n) { return s == n; });
}

AxisRole role_of_standard_name(const std::string &s)
{
    if (one_of(s, {"projection_x_coordinate", "longitude", "grid_longitude"}))
        return AxisRole::easting;
    if (one_of(s, {"projection_y_coordinate", "latitude", "grid_latitude"}))
        return AxisRole::northing;
    if (one_of(s, {"depth", "height", "altitude", "height_above_mean_sea_level",
                   "height_above_reference_ellipsoid", "air_pressure"}))
        return AxisRole::vertical;
    return AxisRole::other;
}

AxisRole role_of_name(const std::string &s)
{
    if (one_of(s, {"x", "easting", "east", "lon", "long", "longitude", "xc",
                   "x_coordinate"}))
        return AxisRole::easting;
    if (one_of(s, {"y", "northing", "north", "lat", "latitude", "yc",
                   "y_coordinate"}))
        return AxisRole::northing;
    if (one_of(s, {"z", "depth", "height", "elevation", "altitude", "level",
                   "lev", "zc", "z_coordinate"}))
        return AxisRole::vertical;
    return AxisRole::other;
}

} // namespace

AxisRole axis_role(const AxisClues &clues)
{
    const std::string axis = lower(clues.axis);
    if (axis == "x")
        return AxisRole::easting;
    if (axis == "y")
        return AxisRole::northing;
    if (axis == "z")
        return AxisRole::vertical;
    if (axis == "t")
        return AxisRole::other;
    const AxisRole by_standard = role_of_standard_name(lower(clues.standard_name));
    if (by_standard != AxisRole::other)
        return by_standard;
    const std::string positive = lower(clues.positive);
    if (positive == "up" || positive == "down")
        return AxisRole::vertical;
    return role_of_name(lower(clues.name));
}

bool positive_down(const AxisClues &clues)
{
    const std::string positive = lower(clues.positive);
    if (!positive.empty())
        return positive == "down";
    return lower(clues.standard_name) == "depth" || lower(clues.name) == "depth";
}

const char *role_name(AxisRole role)
{
    switch (role) {
    case AxisRole::easting:
        return "easting";
    case AxisRole::northing:
        return "northing";
    case AxisRole::vertical:
        return "vertical";
    case AxisRole::other:
        break;
    }
    return "other";
}

RegularAxis regular_axis(const std::vector<double> &centres, bool negate,
                         const std::string &what)
{
    const size_t n = centres.size();
    if (n == 0)
        fail(what, ": has no values (length 0)");
    if (n == 1)
        fail(what, ": has a single value, which does not tell the cell size");
    const double sign = negate ? -1.0 : 1.0;
    const double first = sign * centres.front();
    const double last = sign * centres.back();
    const double step = (last - first) / double(n - 1);
    if (!std::isfinite(first) || !std::isfinite(last) || step == 0)
        fail(what, ": its coordinates do not change (", centres.front(), " to ",
             centres.back(), ")");
    const double tolerance = 1e-5 * std::fabs(step);
    for (size_t i = 0; i < n; ++i) {
        const double c = sign * centres[i];
        if (!std::isfinite(c))
            fail(what, ": coordinate ", i + 1, " is not a number");
        if (i > 0 && (c - sign * centres[i - 1]) * step <= 0)
            fail(what, ": coordinates are not monotonic (", centres[i - 1],
                 " then ", centres[i], " at index ", i + 1, ")");
    }
    for (size_t i = 0; i < n; ++i) {
        const double c = sign * centres[i];
        if (std::fabs(c - (first + double(i) * step)) > tolerance)
            fail(what, ": coordinates are not evenly spaced (", centres[i],
                 " at index ", i + 1, ", a regular axis from ", centres.front(),
                 " by ", sign * step, " has ", sign * (first + double(i) * step),
                 "); resample the file onto a regular grid first");
    }
    RegularAxis a;
    a.size = n;
    a.ascending = step > 0;
    a.resolution = std::fabs(step);
    a.low_edge = std::min(first, last) - a.resolution / 2;
    a.high_edge = std::max(first, last) + a.resolution / 2;
    return a;
}

} // namespace sbrt
