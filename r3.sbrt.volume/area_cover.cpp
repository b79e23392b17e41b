/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The categories covering each model cell, polygons filled
 *            scanline by scanline at the cells' centres within each
 *            polygon's rows, sets of categories merged where areas overlap
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "area_cover.hpp"

#include <algorithm>
#include <cmath>
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
    const sbrt::Frame &f = frame_;
    const double ns = f.ns_res(), ew = f.ew_res();
    // the rows whose centre line may cross the polygon
    double low = INFINITY, high = -INFINITY;
    for (const auto &ring : polygon)
        for (const sbrt::RingPoint &p : ring) {
            low = std::min(low, p.y);
            high = std::max(high, p.y);
        }
    if (!(low <= high))
        return;
    const int first = std::max(0, int(std::floor((f.north - high) / ns - 0.5)));
    const int last = std::min(f.rows - 1, int(std::ceil((f.north - low) / ns - 0.5)));
    const std::vector<int32_t> &counted = within_.cell_zones();
    std::vector<double> crossings;
    for (int r = first; r <= last; ++r) {
        // where the row's centre line crosses each edge (half-open in y,
        // so that a vertex on the line counts once)
        const double y = f.north - (r + 0.5) * ns;
        crossings.clear();
        for (const auto &ring : polygon)
            for (size_t i = 0, n = ring.size(); i < n; ++i) {
                const sbrt::RingPoint &a = ring[i], &b = ring[(i + 1) % n];
                if ((a.y > y) != (b.y > y))
                    crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
            }
        std::sort(crossings.begin(), crossings.end());
        // even-odd: centres in [x0, x1), [x2, x3), ... are inside
        for (size_t k = 0; k + 1 < crossings.size(); k += 2) {
            const double c0 = std::ceil((crossings[k] - f.west) / ew - 0.5);
            const double c1 = std::ceil((crossings[k + 1] - f.west) / ew - 0.5);
            const int from = int(std::max(0.0, c0));
            const int to = int(std::min(double(f.cols), c1));
            for (int c = from; c < to; ++c) {
                const size_t cell = size_t(r) * size_t(f.cols) + size_t(c);
                if (counted[cell] != sbrt::CellZones::NO_ZONE)
                    zone_[cell] = joined(zone_[cell], added);
            }
        }
    }
}

sbrt::CellZones AreaCover::to_cell_zones() const
{
    // CellZones takes polygons only: each run of cells of one zone along a
    // row goes in as the rectangle of those cells, whose centres (and no
    // others) it holds
    sbrt::CellZones cells = sbrt::CellZones::none(frame_, std::max(1, zones()));
    const double ns = frame_.ns_res(), ew = frame_.ew_res();
    const size_t cols = size_t(frame_.cols);
    for (int r = 0; r < frame_.rows; ++r) {
        const int32_t *row = zone_.data() + size_t(r) * cols;
        const double top = frame_.north - r * ns, bottom = frame_.north - (r + 1) * ns;
        for (size_t c = 0; c < cols;) {
            size_t end = c + 1;
            while (end < cols && row[end] == row[c])
                ++end;
            if (row[c] != sbrt::CellZones::NO_ZONE) {
                const double west = frame_.west + double(c) * ew;
                const double east = frame_.west + double(end) * ew;
                cells.add_polygon({{{west, top}, {east, top}, {east, bottom}, {west, bottom}}},
                                  row[c]);
            }
            c = end;
        }
    }
    return cells;
}
