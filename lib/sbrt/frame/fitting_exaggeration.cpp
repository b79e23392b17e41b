/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The vertical exaggeration a model is drawn with when none is
 *            given
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frame/fitting_exaggeration.hpp"

#include <cmath>

#include "frame/coordinate_frame.hpp"

namespace sbrt {

namespace {

/// `value` (> 1) rounded in log scale to the nearest 1, 1.5, 2, 2.5, 3,
/// 4, 5, 6, 8 times a power of ten.
double round_to_typed(double value)
{
    static const double MANTISSAS[] = {1, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10};
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    double best = power, best_distance = INFINITY;
    for (double m : MANTISSAS) {
        const double distance = std::fabs(std::log(value / (m * power)));
        if (distance < best_distance) {
            best_distance = distance;
            best = m * power;
        }
    }
    return best;
}

} // namespace

double fitting_exaggeration(double width, double depth, double thickness)
{
    if (!(thickness > 0) || !(width > 0) || !(depth > 0) || !std::isfinite(width * depth))
        return 1;
    const double wanted = FITTED_THICKNESS_SHARE * std::sqrt(width * depth) / thickness;
    if (!(wanted > 1) || !std::isfinite(wanted))
        return 1;
    return round_to_typed(wanted);
}

double fitting_exaggeration(const Model &model)
{
    return fitting_exaggeration(model.frame(), highest_top_local(model));
}

double fitting_exaggeration(const Frame &f, double top_local)
{
    return fitting_exaggeration(f.cols * f.ew_res(), f.rows * f.ns_res(),
                                top_local * f.tb_res());
}

} // namespace sbrt
