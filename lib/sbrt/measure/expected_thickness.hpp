/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The expected thickness of a column (issue 30, item 2): the sum
 *            over its voxels of the probability (in %, a channel or a sum
 *            of several) times the voxel height, as TNO's cumulative
 *            thicknesses are estimated from GeoTOP's kans_* channels
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_EXPECTED_THICKNESS_HPP
#define SBRT_EXPECTED_THICKNESS_HPP

#include <string>
#include <vector>

#include "format/channels_file.hpp"

namespace sbrt {

/// The channels a probability names ("kans_5+kans_6+kans_7", spaces
/// allowed), each once and each of kind probability (in %); throws
/// sbrt::Error naming an unknown channel (with the model's), one given
/// twice, or one of another kind (saying how to set it).
std::vector<size_t> probability_channels(const PropertyChannels &channels,
                                         const std::string &probability);

/// Sum over the voxels of `cell`'s solid span of p / 100 * `voxel_height`,
/// p the sum of the `summed` channels as meant (stored * scale + offset);
/// a voxel where any of them holds its fill adds nothing. NaN where no
/// voxel of the column has a value (an empty column, fills only).
double expected_thickness(const PropertyChannels &channels, const std::vector<size_t> &summed,
                          uint64_t cell, double voxel_height);

/// \brief The expected volume of a probability in one zone.
struct ExpectedVolume {
    double volume = 0;  ///< cubic map units: expected thicknesses times cell areas
    uint64_t cells = 0; ///< counted cells where it is above 0
};

/// The expected volume of the `summed` channels (a probability in %) in
/// each zone of `zones`: the sum over the zone's cells of their expected
/// thickness times the cell's area; cells in a fixed order (the figures
/// do not depend on threads).
std::vector<ExpectedVolume> expected_volumes(const Model &model,
                                             const PropertyChannels &channels,
                                             const std::vector<size_t> &summed,
                                             const std::vector<int32_t> &cell_zones, int zones);

} // namespace sbrt

#endif
