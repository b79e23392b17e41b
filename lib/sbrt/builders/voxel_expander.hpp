/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Expands an SBRT back to voxels, slice by slice, in any target
 *            3D region (nearest cell, voxel centres)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VOXEL_EXPANDER_HPP
#define SBRT_VOXEL_EXPANDER_HPP

#include "model/model.hpp"

namespace sbrt {

/// \brief Produces the class ids of each slice of `target`, bottom first.
/// A cursor per column walks up its stack, so the whole expansion costs
/// O(voxels + intervals).
class VoxelExpander {
public:
    VoxelExpander(const Model &model, const Frame &target);

    /// Fills `classes` (target rows x cols, row 0 north) with the class ids
    /// of the next slice; NULL_CLASS where empty or outside the model.
    void next_slice(int32_t *classes);

private:
    const Model &model_;
    Frame target_;
    int depth_ = 0;
    std::vector<int64_t> source_cell_; ///< per target column, -1 outside
    std::vector<uint64_t> cursor_;     ///< per target column
    std::vector<uint64_t> end_;        ///< per target column: its stack's end
};

} // namespace sbrt

#endif
