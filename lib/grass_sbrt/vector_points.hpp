/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The points of a vector map that layer= and where= select, read
 *            as v.what.rast reads them (r3.sbrt.what's points=, the
 *            renderer's boreholes=)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VECTOR_POINTS_HPP
#define SBRT_VECTOR_POINTS_HPP

#include <optional>
#include <string>
#include <vector>

#include "layer_table.hpp"
#include "vector_map.hpp"

namespace sbrt_grass {

/// \brief A point of a vector map: its position (z 0 in a 2D map) and its
/// category in the layer read (-1: none).
struct VectorPoint {
    int cat = -1;
    double x = 0, y = 0, z = 0;
};

/// \brief A vector map of points as a module's options choose them.
struct PointChoice {
    const char *option; ///< the option that names the map ("points")
    std::string map;
    std::string layer; ///< layer='s answer: a number (-1: every layer) or a name
    std::string where; ///< where='s SQL clause; empty: every point
};

/// \brief A vector map of points open on the layer its layer= names
/// (layer_number: any other text is an error) and, for where= or another
/// reader, on that layer's table. Errors throw sbrt::Error.
class PointsMap {
public:
    /// `table_for`: a further option that reads the layer's table
    /// ("log_class="), opening it without where=; null: none.
    explicit PointsMap(const PointChoice &choice, const char *table_for = nullptr);

    /// The points (only points: lines, boundaries, centroids and faces are
    /// skipped, with a warning) with a category in the layer (-1: every
    /// point, with its first category of any layer) whose rows where=
    /// selects, in the map's order; none is an error.
    std::vector<VectorPoint> selected();
    Map_info &map() { return vector_.map(); }
    /// The layer's table, where where= or `table_for` opened it.
    LayerTable *table() { return table_ ? &*table_ : nullptr; }

private:
    PointChoice choice_;
    VectorMap vector_;
    int layer_;
    std::optional<LayerTable> table_;
};

} // namespace sbrt_grass

#endif
