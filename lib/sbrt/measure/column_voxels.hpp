/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A column's property channels voxel by voxel, top down, beside
 *            its class (issue 29's profile, issue 30's virtual borehole):
 *            what DINOloket's column view shows per 0.5 m voxel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_VOXELS_HPP
#define SBRT_COLUMN_VOXELS_HPP

#include <cstdint>
#include <vector>

#include "format/channels_file.hpp"
#include "measure/column_log.hpp"

namespace sbrt {

/// \brief One voxel of a column's solid span: its level (0 bottom), its
/// heights in map units, its material (EMPTY in a cave) and every
/// channel's value as meant (stored * scale + offset; NaN for the fill).
struct VoxelValues {
    uint32_t level = 0;
    double top = 0, bottom = 0;
    uint32_t material = EMPTY;
    std::vector<double> values;
};

/// The voxels of `cell`'s solid span, top down, with the values of every
/// channel of `channels` (which belong to `model`); none for an empty
/// column. Throws sbrt::Error for a corrupt block of a channel.
std::vector<VoxelValues> column_voxels(const Model &model, const PropertyChannels &channels,
                                       GridCell cell);

} // namespace sbrt

#endif
