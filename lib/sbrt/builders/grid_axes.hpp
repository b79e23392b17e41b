/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The axes of a gridded file variable: which dimension is
 *            easting, northing or vertical (CF attributes and names), and
 *            the regular cell edges its cell-centre coordinates give
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRID_AXES_HPP
#define SBRT_GRID_AXES_HPP

#include <string>
#include <vector>

namespace sbrt {

enum class AxisRole { easting, northing, vertical, other };

/// \brief What a file says about one dimension (empty where it says nothing).
struct AxisClues {
    std::string name;          ///< dimension (or coordinate variable) name
    std::string axis;          ///< CF `axis`: X, Y, Z, T
    std::string standard_name; ///< CF `standard_name`
    std::string positive;      ///< CF `positive`: up or down
    std::string units;         ///< CF `units`
};

/// Role of a dimension: the CF `axis` attribute first, then
/// `standard_name`, `positive`, then the name (x, easting, lon, ...).
AxisRole axis_role(const AxisClues &clues);
/// Whether a vertical coordinate grows downwards (`positive = down`, or a
/// depth without `positive`).
bool positive_down(const AxisClues &clues);
/// "easting", "northing", "vertical", "other".
const char *role_name(AxisRole role);

/// \brief A regular axis from its cell centres, in either order.
struct RegularAxis {
    double low_edge = 0, high_edge = 0; ///< outer cell edges, low < high
    double resolution = 0;              ///< cell size, > 0
    bool ascending = true;              ///< whether index 0 is the low end
    size_t size = 0;
};

/// The regular axis whose cell centres are `centres` (index order);
/// `negate` turns depths into elevations first. Throws sbrt::Error naming
/// `what` for no values, one value, non-finite, non-monotonic or
/// irregularly spaced centres (relative tolerance 1e-5 of the spacing).
RegularAxis regular_axis(const std::vector<double> &centres, bool negate,
                         const std::string &what);

} // namespace sbrt

#endif
