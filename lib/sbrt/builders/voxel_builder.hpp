/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Builds an SBRT from a categorical voxel model streamed slice by
 *            slice, bottom to top, in O(cells + intervals) memory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VOXEL_BUILDER_HPP
#define SBRT_VOXEL_BUILDER_HPP

#include "model/material_table.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief Run-length encodes every column while slices arrive bottom-up.
///
/// Per cell only the open run (its class and material) is kept; closed runs
/// go to one list that finish() sorts by cell with a stable counting sort.
class VoxelStackBuilder {
public:
    explicit VoxelStackBuilder(const Frame &frame);

    /// One horizontal slice of class ids (NULL_CLASS = empty), row-major,
    /// row 0 north; slices must come in order from depth 0 (bottom) up.
    void add_slice(const int32_t *classes);
    /// Closes the open runs; `legend` gives labels and colours by class id.
    Model finish(const std::vector<Material> &legend = {});

private:
    struct Run {
        uint32_t cell;
        uint32_t material;
        uint32_t top;
    };
    void close_run(uint32_t cell, uint32_t top);

    Frame frame_;
    int depth_ = 0;
    std::vector<int32_t> open_class_;
    std::vector<uint32_t> open_material_;
    std::vector<Run> runs_;
    MaterialTable table_;
};

} // namespace sbrt

#endif
