/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   Which categories cover each model cell: a cell counts for
 *            every category whose area holds its centre (areas of a
 *            category that overlap, one area with several categories),
 *            as one zone per distinct set of categories
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_VOLUME_AREA_COVER_HPP
#define R3_SBRT_VOLUME_AREA_COVER_HPP

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "measure/cell_zones.hpp"

/// \brief Per model cell, the set of categories (indices 0 .. n - 1)
/// whose areas cover its centre, each distinct set numbered as a zone.
class AreaCover {
public:
    /// No cell covered yet; only cells that count in `within` ever will.
    AreaCover(const sbrt::Frame &frame, const sbrt::CellZones &within);

    /// Cells whose centre lies inside `polygon` (even-odd over its rings,
    /// the rule of sbrt::CellZones::add_polygon) gain `categories`
    /// (sorted, distinct).
    void add(const sbrt::Polygon &polygon, const std::vector<int> &categories);

    /// The zones (sets) drawn so far, at least one.
    int zones() const { return int(sets_.size()); }
    /// The categories of zone `zone`, sorted.
    const std::vector<int> &categories(int zone) const { return sets_[size_t(zone)]; }
    /// A zone per cell (CellZones::NO_ZONE: no area covers it).
    const std::vector<int32_t> &cell_zones() const { return zone_; }
    /// The same as sbrt::CellZones, for sbrt::measure_volumes.
    sbrt::CellZones to_cell_zones() const;

private:
    int32_t zone_of(const std::vector<int> &categories);
    int32_t joined(int32_t zone, int32_t added);

    sbrt::Frame frame_;
    const sbrt::CellZones &within_;
    std::vector<int32_t> zone_;
    std::vector<std::vector<int>> sets_;
    std::map<std::vector<int>, int32_t> zone_of_set_;
    std::map<std::pair<int32_t, int32_t>, int32_t> joined_;
};

#endif
