/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Ticks of a figure's axis: multiples of 1, 2 or 5 times a power
 *            of ten, as a person labels an axis
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_AXIS_TICKS_HPP
#define SBRT_AXIS_TICKS_HPP

#include <vector>

namespace sbrt {

/// The smallest step of 1, 2 or 5 times a power of ten that cuts
/// [low, high] into at most `most` parts (`most` at least 1; high > low).
double tick_step(double low, double high, int most);

/// The multiples of `step` in [low, high], ascending (exact multiples:
/// k * step, never an accumulated sum).
std::vector<double> ticks(double low, double high, double step);

} // namespace sbrt

#endif
