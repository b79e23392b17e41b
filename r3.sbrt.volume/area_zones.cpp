/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The areas of a vector map, by category, as zones of the
 *            model's cells (cells whose centre lies inside an area)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <map>

extern "C" {
#include <grass/vector.h>
}

#include "util/error.hpp"
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
            sbrt::fail("areas=", name, ": vector map <", name, "> not found");
        Vect_set_open_level(2);
        if (Vect_open_old(&map_, name.c_str(), "") < 2)
            sbrt::fail("areas=", name, ": vector map <", name,
                       "> has no topology; build it with v.build");
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

} // namespace

Zones area_zones(const sbrt::Model &model, const std::string &name, const std::string &layer,
                 const sbrt::CellZones &region)
{
    AreaMap areas(name);
    struct Map_info *map = areas.map();
    const int field = Vect_get_field_number(map, layer.c_str());
    const int count = Vect_get_num_areas(map);
    // the categories present, in order: one zone each
    std::map<int, int> zone_of;
    int without_category = 0;
    for (int area = 1; area <= count; ++area) {
        if (!Vect_area_alive(map, area) || !Vect_get_area_centroid(map, area))
            continue;
        const int cat = Vect_get_area_cat(map, area, field);
        if (cat < 0)
            ++without_category;
        else
            zone_of.emplace(cat, 0);
    }
    if (zone_of.empty())
        sbrt::fail("areas=", name, ": vector map <", Vect_get_full_name(map),
                   "> has no areas with a category in layer ", layer, " (", count,
                   " areas, ", Vect_get_num_primitives(map, GV_POINT), " points, ",
                   Vect_get_num_primitives(map, GV_LINE), " lines); areas= needs "
                   "boundaries closed around centroids");
    if (without_category)
        G_warning(_("%d areas of <%s> have no category in layer %s and are left out"),
                  without_category, name.c_str(), layer.c_str());
    Zones zones{sbrt::CellZones::none(model.frame(), int(zone_of.size())), {}};
    for (auto &[cat, zone] : zone_of) {
        zone = int(zones.categories.size());
        zones.categories.push_back(cat);
    }
    for (int area = 1; area <= count; ++area) {
        if (!Vect_area_alive(map, area) || !Vect_get_area_centroid(map, area))
            continue;
        const int cat = Vect_get_area_cat(map, area, field);
        if (cat >= 0)
            zones.cells.add_polygon(areas.polygon(area), zone_of[cat], &region);
    }
    return zones;
}
