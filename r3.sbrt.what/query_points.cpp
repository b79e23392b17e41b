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
#include "util/error.hpp"
#include "vector_map.hpp"
extern "C" {
#include <grass/dbmi.h>
#include <grass/vector.h>
}

namespace {

/// An open vector map at level 1 (no topology needed), closed on scope exit.
class PointMap {
public:
    PointMap(const std::string &name, const std::string &layer)
        : points_(Vect_new_line_struct()), cats_(Vect_new_cats_struct())
    {
        // Vect_open_old2 ends the process on a missing map: looked up first
        if (!G_find_vector2(name.c_str(), ""))
            sbrt::fail("Vector map <", name, "> not found (points=): g.list vector lists the maps");
        Vect_set_open_level(1);
        if (Vect_open_old2(&map_, name.c_str(), "", layer.c_str()) < 0)
            sbrt::fail("Unable to open vector map <", name, ">");
        open_ = true;
    }
    ~PointMap()
    {
        Vect_destroy_line_struct(points_);
        Vect_destroy_cats_struct(cats_);
        if (open_)
            Vect_close(&map_);
    }
    PointMap(const PointMap &) = delete;
    PointMap &operator=(const PointMap &) = delete;

    /// The next feature's type (0 at the end); its points and categories.
    int next()
    {
        const int type = Vect_read_next_line(&map_, points_, cats_);
        if (type == -1)
            sbrt::fail("Unable to read vector map <", Vect_get_full_name(&map_), ">");
        return type < 0 ? 0 : type;
    }
    const line_pnts &points() const { return *points_; }
    line_cats *cats() { return cats_; }
    Map_info &map() { return map_; }

private:
    Map_info map_;
    bool open_ = false;
    line_pnts *points_;
    line_cats *cats_;
};

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
            sbrt::fail("coordinates=: point ", i + 1, " (", p.x, ",", p.y,
                       ") is not a position: give finite numbers");
        sbrt::fail("points=", request.points, ": point ", i + 1,
                   p.cat >= 0 ? " (cat " + std::to_string(p.cat) + ")" : std::string(),
                   " lies at ", p.x, ",", p.y,
                   ", not a position: correct it (v.edit) or leave it out with where=");
    }
}

} // namespace

std::vector<QueryPoint> query_points(const WhatRequest &request)
{
    if (request.points.empty()) {
        check_finite(request.coordinates, request);
        return request.coordinates;
    }
    PointMap vector(request.points, request.layer);
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
        sbrt::fail("points=", request.points, " has no points in layer ", request.layer,
                   request.where.empty() ? "" : " that where= selects", " (it holds ", others,
                   " lines, boundaries, centroids or faces): points= needs a vector map of points (layer=-1 "
                   "takes points without categories too)");
    if (others)
        G_warning(_("points=%s: %zu features that are not points skipped"),
                  request.points.c_str(), others);
    check_finite(points, request);
    return points;
}
