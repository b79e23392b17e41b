/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Which model cells a measurement counts, and in which zone:
 *            cells whose centre lies in a window (the region) or inside a
 *            polygon with holes (an area of a vector map)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CELL_ZONES_HPP
#define SBRT_CELL_ZONES_HPP

#include <cstdint>
#include <functional>
#include <vector>

#include "measure/centre_sampling.hpp"
#include "model/model.hpp"

namespace sbrt {

/// A point of a polygon's ring, map coordinates.
struct RingPoint {
    double x, y;
};
/// A polygon: its outer ring and its holes (isles), each ring closed or
/// not (the last point joins the first either way).
using Polygon = std::vector<std::vector<RingPoint>>;

/// \brief Calls `visit(cell)` for each cell of `frame` (row-major index)
/// whose centre lies inside `polygon`, even-odd over all its rings (inside
/// the outer ring, outside every hole), filled scanline by scanline over
/// the polygon's rows only.
void for_each_cell_in_polygon(const Frame &frame, const Polygon &polygon,
                              const std::function<void(size_t cell)> &visit);

/// \brief A zone (0 .. zones - 1) per model cell, or NO_ZONE where the
/// cell does not count.
class CellZones {
public:
    static constexpr int32_t NO_ZONE = -1;

    /// Every cell of `frame` counts in zone 0.
    static CellZones whole(const Frame &frame);
    /// The cells whose centre lies in `window` count, in zone 0.
    static CellZones in_window(const Frame &frame, const GridWindow &window);
    /// No cell counts yet; zones 0 .. zones - 1 to be drawn with add_polygon.
    static CellZones none(const Frame &frame, int zones);
    /// Zone `zone_of_cell[cell]` (or NO_ZONE) for each cell of `frame`.
    static CellZones from_cells(const Frame &frame, int zones,
                                std::vector<int32_t> zone_of_cell);

    /// Cells whose centre lies inside `polygon` (even-odd over all its
    /// rings: inside the outer ring, outside every hole) and that count
    /// in `within` (NO_ZONE: any cell) join `zone`.
    void add_polygon(const Polygon &polygon, int32_t zone, const CellZones *within = nullptr);

    int zones() const { return zones_; }
    int32_t zone(uint64_t cell) const { return zone_[cell]; }
    const std::vector<int32_t> &cell_zones() const { return zone_; }

private:
    Frame frame_;
    int zones_ = 1;
    std::vector<int32_t> zone_;
};

} // namespace sbrt

#endif
