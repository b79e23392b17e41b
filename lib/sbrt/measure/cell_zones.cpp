/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Model cells by zone: a window, polygons filled scanline by
 *            scanline at the cells' centres
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/cell_zones.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

CellZones CellZones::whole(const Frame &frame)
{
    CellZones z;
    z.frame_ = frame;
    z.zones_ = 1;
    z.zone_.assign(frame.cells(), 0);
    return z;
}

CellZones CellZones::none(const Frame &frame, int zones)
{
    if (zones < 1)
        fail("CellZones: at least one zone (", zones, ")");
    CellZones z;
    z.frame_ = frame;
    z.zones_ = zones;
    z.zone_.assign(frame.cells(), NO_ZONE);
    return z;
}

CellZones CellZones::in_window(const Frame &frame, const GridWindow &window)
{
    CellZones z = none(frame, 1);
    const double ns = frame.ns_res(), ew = frame.ew_res();
    for (int r = 0; r < frame.rows; ++r) {
        const double y = frame.north - (r + 0.5) * ns;
        if (!(y < window.north && y >= window.south))
            continue;
        for (int c = 0; c < frame.cols; ++c) {
            const double x = frame.west + (c + 0.5) * ew;
            if (x >= window.west && x < window.east)
                z.zone_[size_t(r) * size_t(frame.cols) + size_t(c)] = 0;
        }
    }
    return z;
}

CellZones CellZones::from_cells(const Frame &frame, int zones,
                                std::vector<int32_t> zone_of_cell)
{
    CellZones z = none(frame, zones);
    if (zone_of_cell.size() != z.zone_.size())
        fail("CellZones::from_cells: ", zone_of_cell.size(), " zones for ", z.zone_.size(),
             " cells");
    for (const int32_t zone : zone_of_cell)
        if (zone != NO_ZONE && (zone < 0 || zone >= zones))
            fail("CellZones::from_cells: zone ", zone, " not in 0 .. ", zones - 1);
    z.zone_ = std::move(zone_of_cell);
    return z;
}

void CellZones::add_polygon(const Polygon &polygon, int32_t zone, const CellZones *within)
{
    if (zone < 0 || zone >= zones_)
        fail("CellZones::add_polygon: zone ", zone, " not in 0 .. ", zones_ - 1);
    for_each_cell_in_polygon(frame_, polygon, [&](size_t cell) {
        if (!within || within->zone_[cell] != NO_ZONE)
            zone_[cell] = zone;
    });
}

void for_each_cell_in_polygon(const Frame &f, const Polygon &polygon,
                              const std::function<void(size_t cell)> &visit)
{
    const double ns = f.ns_res(), ew = f.ew_res();
    // the rows whose centre line may cross the polygon
    double low = INFINITY, high = -INFINITY;
    for (const auto &ring : polygon)
        for (const RingPoint &p : ring) {
            low = std::min(low, p.y);
            high = std::max(high, p.y);
        }
    if (!(low <= high))
        return;
    const int first = std::max(0, int(std::floor((f.north - high) / ns - 0.5)));
    const int last = std::min(f.rows - 1, int(std::ceil((f.north - low) / ns - 0.5)));
    std::vector<double> crossings;
    for (int r = first; r <= last; ++r) {
        // where the row's centre line crosses each edge (half-open in y,
        // so that a vertex on the line counts once)
        const double y = f.north - (r + 0.5) * ns;
        crossings.clear();
        for (const auto &ring : polygon)
            for (size_t i = 0, n = ring.size(); i < n; ++i) {
                const RingPoint &a = ring[i], &b = ring[(i + 1) % n];
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
            for (int c = from; c < to; ++c)
                visit(size_t(r) * size_t(f.cols) + size_t(c));
        }
    }
}

} // namespace sbrt
