/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The classes a vertical section along a line cuts, as a grid of
 *            distance along the line by elevation (a geological profile)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CLASS_PROFILE_HPP
#define SBRT_CLASS_PROFILE_HPP

#include <cstdint>
#include <optional>
#include <vector>

#include "model/model.hpp"
#include "measure/profile_line.hpp"

namespace sbrt {

/// \brief A profile's extent: the line's length by an elevation range.
struct ProfileExtent {
    double bottom = 0, top = 1; ///< map elevations
};

/// \brief Class ids of a section along a line: `cols` columns evenly along
/// the line, each the column of the model's cell under its centre
/// (ProfileLine::column_point); `rows` rows evenly from `top` down to `bottom`, each the class
/// at its centre's elevation. Exact at those points: a point on an
/// interval's top belongs to the interval above, as a voxel holds its
/// bottom face. NULL_CLASS where nothing is (air, a cave, a null, off the
/// model).
struct ClassProfile {
    int rows = 0, cols = 0;
    double length = 0; ///< of the line: the columns span [0, length]
    ProfileExtent extent;
    std::vector<int32_t> classes; ///< row by row, row 0 the highest

    int32_t at(int row, int col) const { return classes[size_t(row) * size_t(cols) + size_t(col)]; }
    /// Elevation of row `row`'s centre.
    double elevation(int row) const
    {
        return extent.top - (row + 0.5) * (extent.top - extent.bottom) / rows;
    }
};

/// The profile of `model` along `line`; throws sbrt::Error for fewer than
/// one row or column, more than `max_cells` cells, or an empty or
/// reversed extent.
ClassProfile class_profile(const Model &model, const ProfileLine &line, int cols, int rows,
                           ProfileExtent extent, uint64_t max_cells = uint64_t(1) << 28);

/// The elevations from the lowest bottom to the highest top of any layer
/// (solid interval) in the cells under `samples` points evenly along the
/// line (column centres, as class_profile takes them); nothing where the
/// line meets no layer.
std::optional<ProfileExtent> solid_extent(const Model &model, const ProfileLine &line,
                                          int samples);

} // namespace sbrt

#endif
