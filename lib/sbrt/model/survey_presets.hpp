/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The survey presets of the tree (presets/NAME.rules, embedded at
 *            build time by tools/embed_presets.sh): by name, and the one a
 *            file's variable identifies itself as
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SURVEY_PRESETS_HPP
#define SBRT_SURVEY_PRESETS_HPP

#include <string>
#include <utility>
#include <vector>

#include "model/legend_rules.hpp"
#include "model/property_channel.hpp"

namespace sbrt {

/// Every embedded preset, parsed once, sorted by name.
const std::vector<SurveyPreset> &survey_presets();
/// Preset `name`; throws sbrt::Error listing the names where none is.
const SurveyPreset &find_preset(const std::string &name);
/// Names, comma-separated (for option lists and messages).
std::string preset_names();
/// The preset whose survey variable `variable` of a file with global
/// attributes `attributes` belongs to, or nullptr.
const SurveyPreset *identify_preset(
    const std::string &variable,
    const std::vector<std::pair<std::string, std::string>> &attributes);

/// Applies the channel lines of `preset` (issue 51) to `channels` as a
/// file gave them: the first line whose pattern matches a channel's name
/// sets its kind, and its unit where the file gave none; a channel the
/// file gave another unit than the line's keeps what its unit says.
/// Returns how many channels it set.
size_t apply_channel_rules(const SurveyPreset &preset, std::vector<ChannelInfo> &channels);

} // namespace sbrt

#endif
