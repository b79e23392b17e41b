/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A class set in one column, in local and in map units
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/column_figures.hpp"

namespace sbrt {

ColumnFigures column_figures(const Model &model, uint64_t cell, const ClassSet &set)
{
    return model.visit_stack(cell, [&](const auto *first, const auto *last) {
        return column_figures(first, last, set);
    });
}

MapFigures map_figures(const Frame &frame, const ColumnFigures &f)
{
    const double res = frame.tb_res();
    MapFigures m;
    m.top = frame.bottom + f.top * res;
    m.base = frame.bottom + f.base * res;
    m.thickness = f.thickness * res;
    m.depth = (f.surface - f.top) * res;
    m.layers = f.layers;
    return m;
}

} // namespace sbrt
