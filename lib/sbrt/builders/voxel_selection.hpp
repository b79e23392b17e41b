/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A selection by property (issue 29): the model with only the
 *            voxels whose property meets a condition solid (a probability
 *            shell, e.g. P(sand) >= 60 %), built in one pass over the
 *            channels, traced exactly as any model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VOXEL_SELECTION_HPP
#define SBRT_VOXEL_SELECTION_HPP

#include <string>
#include <vector>

#include "format/channels_file.hpp"
#include "model/model.hpp"

namespace sbrt {

/// How a property is compared with the threshold.
enum class Comparison { greater_equal, greater, less_equal, less, equal, not_equal };

/// \brief `sum of channels (as meant) OP threshold`.
struct Selection {
    std::vector<size_t> channels;
    Comparison comparison = Comparison::greater_equal;
    double threshold = 0;

    bool holds(double value) const;
};

/// Parses "kans_5+kans_6 >= 60" (operators >=, >, <=, <, ==, !=; spaces
/// optional) against `channels`; throws sbrt::Error naming what is wrong.
Selection parse_selection(const std::string &text, const PropertyChannels &channels);

/// `model` with every voxel of its solid spans that does not meet
/// `selection` made EMPTY (fills never do), the others keeping their
/// class; adjacent runs merged. Decodes every block of the channels
/// named (on `threads` threads).
Model select_voxels(const Model &model, const PropertyChannels &channels,
                    const Selection &selection, unsigned threads = 0);

} // namespace sbrt

#endif
