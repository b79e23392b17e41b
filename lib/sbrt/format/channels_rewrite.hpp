/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Rewrites the `channels` member of an SBRT with new units,
 *            kinds and long names (issue 51), atomically, the other
 *            members hard-linked into the new directory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CHANNELS_REWRITE_HPP
#define SBRT_CHANNELS_REWRITE_HPP

#include <string>
#include <vector>

#include "format/channels_file.hpp"

namespace sbrt {

/// Replaces the `channels` member of the SBRT directory, whose channels
/// as read are `channels`, with one whose channels have the units, kinds
/// and long names of `infos` (PropertyChannels::write_with: the blocks
/// copied as they are), and appends `history` to its `hist`, atomically
/// (AtomicDirectory): the other members are hard-linked into the new
/// directory (copied where the file system cannot link). The caller holds
/// the SBRT's writers' lock. Throws sbrt::Error.
void rewrite_channels(const std::string &directory, const PropertyChannels &channels,
                      const std::vector<ChannelInfo> &infos, const std::string &history);

} // namespace sbrt

#endif
