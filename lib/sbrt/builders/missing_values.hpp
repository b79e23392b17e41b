/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The values of a file variable that mean "no data": CF
 *            `_FillValue`, `missing_value` and the valid range
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MISSING_VALUES_HPP
#define SBRT_MISSING_VALUES_HPP

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sbrt {

/// \brief A value is missing when it is NaN, equals one of `exact` or lies
/// outside [valid_min, valid_max].
struct MissingValues {
    std::vector<double> exact;
    double valid_min = -std::numeric_limits<double>::infinity();
    double valid_max = std::numeric_limits<double>::infinity();

    bool is_missing(double v) const
    {
        if (std::isnan(v) || v < valid_min || v > valid_max)
            return true;
        return std::find(exact.begin(), exact.end(), v) != exact.end();
    }
};

} // namespace sbrt

#endif
