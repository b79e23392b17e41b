/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A profile's line: a polyline in map coordinates unfolded into
 *            the distance along it (a geological cross-section's x axis)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PROFILE_LINE_HPP
#define SBRT_PROFILE_LINE_HPP

#include <vector>

#include <glm/vec2.hpp>

namespace sbrt {

/// \brief A line of two or more vertices, measured along its segments
/// (planimetric, in map units): distance 0 at the first vertex.
class ProfileLine {
public:
    /// Drops vertices that repeat the one before; throws sbrt::Error where
    /// a coordinate is not finite or fewer than two distinct vertices stay.
    explicit ProfileLine(std::vector<glm::dvec2> vertices);

    const std::vector<glm::dvec2> &vertices() const { return vertices_; }
    /// Distance of each vertex from the first (0 first, length() last).
    const std::vector<double> &vertex_distances() const { return distances_; }
    double length() const { return distances_.back(); }
    /// The map point at distance `d` along the line (clamped to its ends).
    glm::dvec2 point_at(double d) const;
    /// The distance of the centre of step `col` of `cols` even steps along
    /// the line, and its map point: where a profile's column samples.
    double column_distance(int col, int cols) const { return (col + 0.5) * length() / cols; }
    glm::dvec2 column_point(int col, int cols) const
    {
        return point_at(column_distance(col, cols));
    }

private:
    std::vector<glm::dvec2> vertices_;
    std::vector<double> distances_;
};

} // namespace sbrt

#endif
