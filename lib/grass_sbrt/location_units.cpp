/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The unit of the current location's lengths and heights
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "location_units.hpp"

#include "grass.hpp"

namespace sbrt_grass {

std::string location_length_unit()
{
    if (G_projection() == PROJECTION_XY)
        return "map units";
    switch (G_database_unit()) {
    case U_METERS:
        return "m";
    case U_FEET:
        return "ft";
    case U_USFEET:
        return "ftUS";
    default:
        return G_database_unit_name(TRUE);
    }
}

} // namespace sbrt_grass
