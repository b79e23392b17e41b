/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A class set in one column: top, base, thickness, layers and
 *            depth below the model's surface, from the column's intervals
 *            (one pass over them, never a voxel loop)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_FIGURES_HPP
#define SBRT_COLUMN_FIGURES_HPP

#include <cstdint>

#include "measure/class_set.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief A class set in one column, in local units (tb_res above the
/// frame bottom), exact at the model's heights.
struct ColumnFigures {
    double top = 0;       ///< highest top of the set's intervals
    double base = 0;      ///< lowest bottom of the set's intervals
    double thickness = 0; ///< the set's intervals together
    uint32_t layers = 0;  ///< runs of adjacent set intervals; 0: set absent
    double surface = 0;   ///< highest top of any solid interval
    bool present() const { return layers > 0; }
};

/// \brief The same in map units: elevations, lengths, a count.
struct MapFigures {
    double top = 0;       ///< elevation of the set's highest top
    double base = 0;      ///< elevation of its lowest bottom
    double thickness = 0; ///< total thickness
    double depth = 0;     ///< surface elevation minus top
    uint32_t layers = 0;
};

/// Figures of `set` over the intervals [first, last) of one stack
/// (Interval or CompactInterval): O(intervals).
template <typename Record>
ColumnFigures column_figures(const Record *first, const Record *last, const ClassSet &set)
{
    ColumnFigures f;
    double below = 0;
    bool in_run = false;
    for (const Record *r = first; r != last; ++r) {
        const double top = double(r->top);
        if (set.contains(r->material)) {
            if (!in_run) {
                ++f.layers;
                if (f.layers == 1)
                    f.base = below;
            }
            f.thickness += top - below;
            f.top = top;
            in_run = true;
        }
        else {
            in_run = false;
        }
        if (r->material != EMPTY)
            f.surface = top;
        below = top;
    }
    return f;
}

/// Figures of `set` in model cell `cell`.
ColumnFigures column_figures(const Model &model, uint64_t cell, const ClassSet &set);

/// The figures in map units of frame `frame` (elevation = bottom +
/// local * tb_res); meaningful where `f.present()`.
MapFigures map_figures(const Frame &frame, const ColumnFigures &f);

} // namespace sbrt

#endif
