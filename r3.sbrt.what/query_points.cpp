/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   Query points from coordinates= or a vector points map, read
 *            as v.what.rast reads them (layer=, where=: PointsMap)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "query_points.hpp"

#include <cmath>
#include <string>

#include "module_errors.hpp"
#include "vector_points.hpp"

namespace {

/// Refuses a point that is no position (coordinates=nan,nan or inf, a
/// vector map holding nan): it would be logged as outside, with
/// coordinates that json cannot hold.
void check_finite(const std::vector<QueryPoint> &points, const WhatRequest &request)
{
    for (size_t i = 0; i < points.size(); ++i) {
        const QueryPoint &p = points[i];
        if (std::isfinite(p.x) && std::isfinite(p.y))
            continue;
        if (request.points.empty())
            sbrt_grass::fail_with(
                _("coordinates=: point %zu (%g,%g) is not a position: give finite "
                  "numbers"),
                i + 1, p.x, p.y);
        const std::string cat = p.cat >= 0 ? " (cat " + std::to_string(p.cat) + ")" : "";
        sbrt_grass::fail_with(
            _("points=%s: point %zu%s lies at %g,%g, not a position: correct it "
              "(v.edit) or leave it out with where="),
            request.points.c_str(), i + 1, cat.c_str(), p.x, p.y);
    }
}

} // namespace

std::vector<QueryPoint> query_points(const WhatRequest &request)
{
    if (request.points.empty()) {
        check_finite(request.coordinates, request);
        return request.coordinates;
    }
    sbrt_grass::PointsMap map({"points", request.points, request.layer, request.where});
    std::vector<QueryPoint> points;
    for (const sbrt_grass::VectorPoint &p : map.selected())
        points.push_back({p.x, p.y, p.cat});
    check_finite(points, request);
    return points;
}
