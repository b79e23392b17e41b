/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Builds an SBRT from whole voxel columns arriving cell by cell
 *            in the model's order (files whose vertical axis varies fastest)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_BUILDER_HPP
#define SBRT_COLUMN_BUILDER_HPP

#include "model/material_table.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief Run-length encodes each column as it arrives and appends its
/// stack: memory is the model itself (or, with take_rows, the rows not
/// yet taken), nothing per voxel and no sort.
class ColumnStackBuilder {
public:
    explicit ColumnStackBuilder(const Frame &frame);

    /// The column of the next cell (row-major, row 0 north): frame.depths
    /// class ids from the bottom up (NULL_CLASS = empty).
    void add_column(const int32_t *classes);
    /// \brief Runs of one class up to voxel boundary `top` (exclusive).
    struct ClassRun {
        int32_t id;
        uint32_t top;
    };
    /// The column of the next cell as runs from the bottom up, their tops
    /// rising to frame.depths; neighbours of one class are merged.
    void add_runs(const ClassRun *runs, size_t count);
    /// Cells added so far (those taken by take_rows included).
    uint64_t cells_done() const { return cells_taken_ + sizes_.size(); }
    /// Whole rows added and not yet taken.
    int rows_ready() const { return int(sizes_.size() / uint64_t(frame_.cols)); }
    /// The first `count` rows not yet taken, as a model of their own (its
    /// frame frame_rows of the model's, its materials those met so far),
    /// and drops them: an import holds a band of rows, not the model. A
    /// material keeps its index in every later band and in finish()'s
    /// model. Throws sbrt::Error where fewer rows are ready.
    Model take_rows(int count, const std::vector<Material> &legend = {});
    /// The model once every cell has its column (the rows not taken:
    /// after take_rows, the last band); `legend` gives labels and colours
    /// by class id.
    Model finish(const std::vector<Material> &legend = {});
    /// The materials met so far, EMPTY first (labels and colours from
    /// `legend`).
    std::vector<Material> materials(const std::vector<Material> &legend = {}) const
    {
        return table_.materials(legend);
    }

private:
    /// Appends a column's runs to `intervals`; returns its stack size.
    template <typename Records>
    uint32_t append(Records &intervals, const ClassRun *runs, size_t count);

    /// The model of `rows` rows from the first not taken, of the first
    /// `intervals` records.
    template <typename Records>
    Model band_model(Records &intervals, int rows, const std::vector<Material> &legend);

    Frame frame_;
    uint64_t cells_taken_ = 0;
    std::vector<uint32_t> sizes_; ///< per cell added and not taken
    /// the stacks, 4 bytes an interval where the depths allow (always
    /// but past 65535 layers), else 8
    bool compact_;
    CompactIntervals compact_intervals_;
    Intervals intervals_;
    MaterialTable table_;
    std::vector<ClassRun> runs_; ///< add_column's runs
};

} // namespace sbrt

#endif
