/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Ticks of a figure's axis
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/axis_ticks.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

double tick_step(double low, double high, int most)
{
    if (!std::isfinite(low) || !std::isfinite(high) || !(high > low))
        fail("an axis must rise (", low, " to ", high, ")");
    const double least = (high - low) / std::max(most, 1);
    double ten = std::pow(10.0, std::floor(std::log10(least)));
    for (;; ten *= 10)
        for (double m : {1.0, 2.0, 5.0})
            if (m * ten >= least * (1 - 1e-12))
                return m * ten;
}

std::vector<double> ticks(double low, double high, double step)
{
    if (!(step > 0) || !std::isfinite(step))
        fail("an axis's tick step must be positive (", step, ")");
    const double slack = 1e-9 * step;
    std::vector<double> values;
    for (double k = std::ceil((low - slack) / step); k * step <= high + slack; ++k)
        values.push_back(k * step);
    return values;
}

} // namespace sbrt
