/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The points of a vector map that layer= and where= select
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "vector_points.hpp"

#include <algorithm>

#include "grass.hpp"
#include "module_errors.hpp"

namespace sbrt_grass {

PointsMap::PointsMap(const PointChoice &choice, const char *table_for)
    : choice_(choice), vector_(choice.map, choice.layer.c_str(), choice.option),
      layer_(layer_number(vector_.map(), choice.layer))
{
    if (!choice_.where.empty() || table_for)
        table_.emplace(vector_.map(), layer_, choice_.where.empty() ? table_for : "where=");
}

std::vector<VectorPoint> PointsMap::selected()
{
    const bool where = !choice_.where.empty();
    std::vector<int> chosen;
    if (where)
        chosen = selected_categories(*table_, choice_.where);
    std::vector<VectorPoint> points;
    size_t others = 0;
    while (const int type = vector_.next()) {
        // points only, as v.what.rast's default type=point: the centroids
        // of an area map are no points
        if (type != GV_POINT) {
            ++others;
            continue;
        }
        // its (first) category in layer=; layer=-1: every point, with its
        // first category of any layer
        VectorPoint p;
        if (layer_ > 0) {
            if (!Vect_cat_get(vector_.cats(), layer_, &p.cat))
                continue; // not in layer=
        }
        else if (vector_.cats()->n_cats > 0) {
            p.cat = vector_.cats()->cat[0];
        }
        if (where && !std::binary_search(chosen.begin(), chosen.end(), p.cat))
            continue;
        p.x = vector_.points().x[0];
        p.y = vector_.points().y[0];
        p.z = vector_.points().z[0];
        points.push_back(p);
    }
    if (points.empty())
        fail_with(_("%s=%s has no points in layer %s%s (it holds %zu lines, boundaries, "
                    "centroids or faces): %s= needs a vector map of points (layer=-1 "
                    "takes points without categories too)"),
                  choice_.option, choice_.map.c_str(), choice_.layer.c_str(),
                  where ? _(" that where= selects") : "", others, choice_.option);
    if (others)
        G_warning(_("%s=%s: %zu features that are not points skipped"), choice_.option,
                  choice_.map.c_str(), others);
    return points;
}

} // namespace sbrt_grass
