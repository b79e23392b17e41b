/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   A property channel's unit and kind set after import (issue
 *            51): GeoTOP delivers its kans_* without units, and an SBRT
 *            imported without the preset gets them here
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SUPPORT_CHANNEL_CHANGES_HPP
#define R3_SBRT_SUPPORT_CHANNEL_CHANGES_HPP

#include <optional>
#include <string>
#include <vector>

#include "format/channels_file.hpp"
#include "model/property_channel.hpp"

/// The longest unit support sets (bytes).
constexpr size_t MAX_UNIT_BYTES = 64;

/// \brief What channel=, unit= and kind= ask for, checked as text.
struct ChannelChange {
    std::vector<std::string> names;
    std::optional<std::string> unit; ///< "" for unit=none
    std::optional<sbrt::ChannelKind> kind;
};

/// The change the options ask for (`names`: channel='s answers, `unit`
/// and `kind` null where not given); a fatal error where a unit is not
/// printable or too long, or a name is given twice.
ChannelChange read_channel_change(char **names, const char *unit, const char *kind);

/// The channels of SBRT `sbrt_name` (`channels`, null where it has none)
/// with `change` made: a fatal error naming a channel it does not have,
/// and where a probability would not be in %. Says what changed.
std::vector<sbrt::ChannelInfo> changed_channels(const sbrt::PropertyChannels *channels,
                                                const ChannelChange &change,
                                                const char *sbrt_name);

#endif
