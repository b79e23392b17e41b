/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The unit of the current location's lengths and heights, as a
 *            log, a map's units and an axis name it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_LOCATION_UNITS_HPP
#define SBRT_LOCATION_UNITS_HPP

#include <string>

namespace sbrt_grass {

/// "m", "ft" or "ftUS" (GRASS's unit name otherwise); "map units" in an
/// XY location, whose lengths have no unit.
std::string location_length_unit();

} // namespace sbrt_grass

#endif
