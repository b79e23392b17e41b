/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A profile's line unfolded into the distance along it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/profile_line.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.hpp"

namespace sbrt {

ProfileLine::ProfileLine(std::vector<glm::dvec2> vertices)
{
    for (const glm::dvec2 &v : vertices) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
            fail("a profile line's vertex is not a finite coordinate");
        if (vertices_.empty() || v != vertices_.back())
            vertices_.push_back(v);
    }
    if (vertices_.size() < 2)
        fail("a profile line needs two distinct points (", vertices.size(),
             " given, ", vertices_.size(), " distinct)");
    distances_.reserve(vertices_.size());
    distances_.push_back(0);
    for (size_t i = 1; i < vertices_.size(); ++i)
        distances_.push_back(distances_.back() + glm::distance(vertices_[i - 1], vertices_[i]));
    if (!std::isfinite(length()))
        fail("a profile line's length is not finite");
}

glm::dvec2 ProfileLine::point_at(double d) const
{
    if (!(d > 0))
        return vertices_.front();
    if (d >= length())
        return vertices_.back();
    // the segment whose end lies beyond d
    const size_t end = size_t(std::upper_bound(distances_.begin(), distances_.end(), d) -
                              distances_.begin());
    const double from = distances_[end - 1], to = distances_[end];
    const double t = to > from ? (d - from) / (to - from) : 0;
    return vertices_[end - 1] + t * (vertices_[end] - vertices_[end - 1]);
}

} // namespace sbrt
