/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The column under a map point as a log: its intervals top to
 *            bottom at the model's true heights in map units (a virtual
 *            borehole)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_LOG_HPP
#define SBRT_COLUMN_LOG_HPP

#include <cstdint>
#include <optional>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief The map elevation of local height `local` (units of tb_res above
/// the frame's bottom): frame.bottom + local * tb_res.
inline double map_height(const Frame &frame, double local)
{
    return frame.bottom + local * frame.tb_res();
}

/// \brief One entry of a column log: a layer of one material or a gap
/// (EMPTY: a cave, air under an overhang) between two layers; heights in
/// map units.
struct LogEntry {
    uint32_t material = EMPTY; ///< index into Model::materials()
    double top = 0, bottom = 0;

    double thickness() const { return top - bottom; }
    bool is_gap() const { return material == EMPTY; }
};

/// \brief The intervals of one column, top to bottom: the layers and the
/// gaps between them. The empty space below the lowest layer (where the
/// column does not reach the frame's bottom) and the air above the highest
/// one are not entries: the log runs from the top of its highest layer to
/// the bottom of its lowest.
struct ColumnLog {
    GridCell cell;
    std::vector<LogEntry> entries;

    /// Whether the column holds no layer at all.
    bool is_empty() const { return entries.empty(); }
    /// The number of layers (entries that are not gaps).
    size_t layer_count() const;
};

/// \brief The log of `cell` (which must lie in the model's frame; throws
/// sbrt::Error where it does not).
ColumnLog column_log(const Model &model, GridCell cell);

} // namespace sbrt

#endif
