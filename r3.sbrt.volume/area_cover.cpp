/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The categories covering each model cell, polygons filled
 *            scanline by scanline at the cells' centres within each
 *            polygon's rows, sets of categories merged where areas overlap
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "area_cover.hpp"

#include <algorithm>
#include <iterator>

AreaCover::AreaCover(const sbrt::Frame &frame, const sbrt::CellZones &within)
    : frame_(frame), within_(within), zone_(frame.cells(), sbrt::CellZones::NO_ZONE)
{
}

int32_t AreaCover::zone_of(const std::vector<int> &categories)
{
    const auto [it, added] = zone_of_set_.emplace(categories, int32_t(sets_.size()));
    if (added)
        sets_.push_back(categories);
    return it->second;
}

int32_t AreaCover::joined(int32_t zone, int32_t added)
{
    if (zone == sbrt::CellZones::NO_ZONE || zone == added)
        return added;
    const auto key = std::make_pair(zone, added);
    const auto known = joined_.find(key);
    if (known != joined_.end())
        return known->second;
    std::vector<int> both;
    std::set_union(sets_[size_t(zone)].begin(), sets_[size_t(zone)].end(),
                   sets_[size_t(added)].begin(), sets_[size_t(added)].end(),
                   std::back_inserter(both));
    const int32_t result = zone_of(both);
    joined_.emplace(key, result);
    return result;
}

void AreaCover::add(const sbrt::Polygon &polygon, const std::vector<int> &categories)
{
    const int32_t added = zone_of(categories);
    const std::vector<int32_t> &counted = within_.cell_zones();
    sbrt::for_each_cell_in_polygon(frame_, polygon, [&](size_t cell) {
        if (counted[cell] != sbrt::CellZones::NO_ZONE)
            zone_[cell] = joined(zone_[cell], added);
    });
}

sbrt::CellZones AreaCover::to_cell_zones() const
{
    return sbrt::CellZones::from_cells(frame_, std::max(1, zones()), zone_);
}
