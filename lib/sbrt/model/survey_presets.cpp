/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The embedded survey presets
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/survey_presets.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cstddef>
#include <sstream>

#include "util/error.hpp"

namespace sbrt {

// build/presets.cpp, written by tools/embed_presets.sh: file name, text
extern const char *const PRESET_FILES[][2];
extern const size_t PRESET_FILE_COUNT;

const std::vector<SurveyPreset> &survey_presets()
{
    static const std::vector<SurveyPreset> presets = [] {
        std::vector<SurveyPreset> all;
        for (size_t i = 0; i < PRESET_FILE_COUNT; ++i) {
            std::istringstream in(PRESET_FILES[i][1]);
            all.push_back(parse_preset(in, std::string("presets/") + PRESET_FILES[i][0]));
        }
        std::sort(all.begin(), all.end(), [](const SurveyPreset &a, const SurveyPreset &b) {
            return a.name < b.name;
        });
        return all;
    }();
    return presets;
}

std::string preset_names()
{
    std::string names;
    for (const SurveyPreset &p : survey_presets())
        names += (names.empty() ? "" : ",") + p.name;
    return names;
}

const SurveyPreset &find_preset(const std::string &name)
{
    for (const SurveyPreset &p : survey_presets())
        if (p.name == name)
            return p;
    fail("preset ", name, " is not known (known: ", preset_names(), ")");
}

const SurveyPreset *identify_preset(
    const std::string &variable,
    const std::vector<std::pair<std::string, std::string>> &attributes)
{
    for (const SurveyPreset &p : survey_presets())
        if (preset_matches(p, variable, attributes))
            return &p;
    return nullptr;
}

size_t apply_channel_rules(const SurveyPreset &preset, std::vector<ChannelInfo> &channels)
{
    size_t set = 0;
    for (ChannelInfo &c : channels)
        for (const ChannelRule &rule : preset.channels) {
            if (fnmatch(rule.pattern.c_str(), c.name.c_str(), 0) != 0)
                continue;
            if (c.unit.empty() || rule.unit.empty() || rule.unit == c.unit) {
                if (c.unit.empty())
                    c.unit = rule.unit;
                c.kind = rule.kind;
                ++set;
            }
            break; // the first line that names the channel
        }
    return set;
}

} // namespace sbrt
