/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   Query points from coordinates= or a vector points map, read
 *            as v.what.rast reads them (level 1, layer=, where=)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "query_points.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "layer_table.hpp"
#include "module_errors.hpp"
#include "vector_map.hpp"

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
    sbrt_grass::VectorMap vector(request.points, request.layer.c_str(), "points");
    const int layer = sbrt_grass::layer_number(vector.map(), request.layer);
    std::vector<int> selected;
    if (!request.where.empty()) {
        sbrt_grass::LayerTable table(vector.map(), layer, "where=");
        selected = sbrt_grass::selected_categories(table, request.where);
    }
    std::vector<QueryPoint> points;
    size_t others = 0;
    while (const int type = vector.next()) {
        // points only, as v.what.rast's default type=point: the centroids
        // of an area map are no query points
        if (type != GV_POINT) {
            ++others;
            continue;
        }
        // its (first) category in layer=; layer=-1: every point, with its
        // first category of any layer
        QueryPoint p;
        if (layer > 0) {
            if (!Vect_cat_get(vector.cats(), layer, &p.cat))
                continue; // not in layer=
        }
        else if (vector.cats()->n_cats > 0) {
            p.cat = vector.cats()->cat[0];
        }
        if (!request.where.empty() &&
            !std::binary_search(selected.begin(), selected.end(), p.cat))
            continue;
        p.x = vector.points().x[0];
        p.y = vector.points().y[0];
        points.push_back(p);
    }
    if (points.empty())
        sbrt_grass::fail_with(
            _("points=%s has no points in layer %s%s (it holds %zu lines, "
              "boundaries, centroids or faces): points= needs a vector map of "
              "points (layer=-1 takes points without categories too)"),
            request.points.c_str(), request.layer.c_str(),
            request.where.empty() ? "" : _(" that where= selects"), others);
    if (others)
        G_warning(_("points=%s: %zu features that are not points skipped"),
                  request.points.c_str(), others);
    check_finite(points, request);
    return points;
}
