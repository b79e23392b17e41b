/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Column logs: a stack's intervals at map heights, top to bottom
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/column_log.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

size_t ColumnLog::layer_count() const
{
    return size_t(std::count_if(entries.begin(), entries.end(),
                                [](const LogEntry &e) { return !e.is_gap(); }));
}

ColumnLog column_log(const Model &model, GridCell cell)
{
    const Frame &frame = model.frame();
    if (cell.row < 0 || cell.row >= frame.rows || cell.col < 0 || cell.col >= frame.cols)
        fail("column_log: cell (row ", cell.row, ", col ", cell.col,
             ") outside the model's ", frame.rows, " x ", frame.cols, " cells");
    ColumnLog log;
    log.cell = cell;
    // bottom up, as the stack holds them: each interval starts at the
    // previous top (0 for the first); a leading EMPTY run is no gap (no
    // layer lies below it) and a stack never ends in EMPTY
    model.visit_stack(model.cell_index(cell.row, cell.col), [&](const auto *first,
                                                                const auto *last) {
        log.entries.reserve(size_t(last - first));
        double below = 0;
        for (const auto *r = first; r != last; ++r) {
            const double top = double(r->top);
            const uint32_t material = r->material;
            if (material != EMPTY || !log.entries.empty())
                log.entries.push_back(
                    {material, map_height(frame, top), map_height(frame, below)});
            below = top;
        }
    });
    std::reverse(log.entries.begin(), log.entries.end());
    return log;
}

} // namespace sbrt
