/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The areas of a vector map, by category, as zones of the
 *            model's cells (cells whose centre lies inside an area count
 *            for each of its categories)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <map>
#include <utility>

extern "C" {
#include <grass/vector.h>
}

#include "area_cover.hpp"
#include "vector_map.hpp"
#include "module_errors.hpp"
#include "volume.hpp"

namespace {

/// The points of `line` as a ring.
std::vector<sbrt::RingPoint> ring_of(const struct line_pnts *line)
{
    std::vector<sbrt::RingPoint> ring;
    ring.reserve(size_t(line->n_points));
    for (int i = 0; i < line->n_points; ++i)
        ring.push_back({line->x[i], line->y[i]});
    return ring;
}

/// \brief A vector map open with topology, closed on every way out.
class AreaMap {
public:
    explicit AreaMap(const std::string &name)
    {
        // Vect_open_old2 ends the process on a missing map: looked up first
        if (!G_find_vector2(name.c_str(), ""))
            sbrt_grass::fail_with(_("areas=%s: vector map <%s> not found"), name.c_str(),
                                  name.c_str());
        Vect_set_open_level(2);
        if (Vect_open_old(&map_, name.c_str(), "") < 2)
            sbrt_grass::fail_with(_("areas=%s: vector map <%s> has no topology; build it with "
                                    "v.build"),
                                  name.c_str(), name.c_str());
        points_ = Vect_new_line_struct();
    }
    ~AreaMap()
    {
        Vect_destroy_line_struct(points_);
        Vect_close(&map_);
    }
    AreaMap(const AreaMap &) = delete;
    AreaMap &operator=(const AreaMap &) = delete;

    struct Map_info *map() { return &map_; }
    /// Area `area`: its outer ring, then its isles.
    sbrt::Polygon polygon(int area)
    {
        sbrt::Polygon polygon;
        Vect_get_area_points(&map_, area, points_);
        polygon.push_back(ring_of(points_));
        for (int i = 0; i < Vect_get_area_num_isles(&map_, area); ++i) {
            Vect_get_isle_points(&map_, Vect_get_area_isle(&map_, area, i), points_);
            polygon.push_back(ring_of(points_));
        }
        return polygon;
    }

private:
    struct Map_info map_;
    struct line_pnts *points_ = nullptr;
};

/// \brief An area of the map and its categories in the layer.
struct CategorisedArea {
    int area;
    std::vector<int> categories; ///< sorted, distinct
};

/// The live areas with a centroid, each with its centroid's categories in
/// `field` (several where v.in.ogr cut overlapping polygons into one
/// area); `without` counts those with none.
std::vector<CategorisedArea> categorised_areas(struct Map_info *map, int field, int &without)
{
    std::vector<CategorisedArea> found;
    struct line_cats *cats = Vect_new_cats_struct();
    without = 0;
    for (int area = 1, count = Vect_get_num_areas(map); area <= count; ++area) {
        if (!Vect_area_alive(map, area) || Vect_get_area_cats(map, area, cats) != 0)
            continue;
        CategorisedArea a{area, {}};
        for (int i = 0; i < cats->n_cats; ++i)
            if (cats->field[i] == field)
                a.categories.push_back(cats->cat[i]);
        std::sort(a.categories.begin(), a.categories.end());
        a.categories.erase(std::unique(a.categories.begin(), a.categories.end()),
                           a.categories.end());
        if (a.categories.empty())
            ++without;
        else
            found.push_back(std::move(a));
    }
    Vect_destroy_cats_struct(cats);
    return found;
}

} // namespace

Zones area_zones(const sbrt::Frame &frame, const std::string &name, const std::string &layer,
                 const sbrt::CellZones &region)
{
    AreaMap areas(name);
    struct Map_info *map = areas.map();
    const int field = sbrt_grass::layer_number(*map, layer);
    int without_category = 0;
    const std::vector<CategorisedArea> found = categorised_areas(map, field, without_category);
    if (found.empty())
        sbrt_grass::fail_with(
            _("areas=%s: vector map <%s> has no areas with a category in layer %s "
              "(%d areas, %d points, %d lines); areas= needs boundaries "
              "closed around centroids"),
            name.c_str(), Vect_get_full_name(map), layer.c_str(), int(Vect_get_num_areas(map)),
            int(Vect_get_num_primitives(map, GV_POINT)),
            int(Vect_get_num_primitives(map, GV_LINE)));
    if (without_category)
        G_warning(_("%d areas of <%s> have no category in layer %s and are left out"),
                  without_category, name.c_str(), layer.c_str());
    // the categories present, in order: one row each
    std::map<int, int> index_of;
    for (const CategorisedArea &a : found)
        for (int cat : a.categories)
            index_of.emplace(cat, 0);
    Zones zones{region, {}, {}};
    for (auto &[cat, index] : index_of) {
        index = int(zones.categories.size());
        zones.categories.push_back(cat);
    }
    // a cell counts for each category whose area holds its centre: areas
    // of a category, or of several, may overlap (an area's isles are its
    // holes; an island in a hole is an area of its own)
    AreaCover cover(frame, region);
    std::vector<int> indices;
    for (const CategorisedArea &a : found) {
        indices.clear();
        for (int cat : a.categories)
            indices.push_back(index_of[cat]);
        cover.add(areas.polygon(a.area), indices);
    }
    zones.cells = cover.to_cell_zones();
    for (int z = 0; z < cover.zones(); ++z)
        zones.counts_for.push_back(cover.categories(z));
    return zones;
}
