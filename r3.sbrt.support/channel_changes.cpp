/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   A property channel's unit and kind: checked and made
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "channel_changes.hpp"

#include <algorithm>

#include "grass.hpp"
#include "util/safe_text.hpp"

ChannelChange read_channel_change(char **names, const char *unit, const char *kind)
{
    ChannelChange change;
    for (size_t i = 0; names && names[i]; ++i) {
        const std::string name = names[i];
        if (std::find(change.names.begin(), change.names.end(), name) != change.names.end())
            G_fatal_error(_("channel= names '%s' twice"), sbrt::printable(name).c_str());
        change.names.push_back(name);
    }
    if (unit) {
        const std::string text = std::string(unit) == "none" ? "" : unit;
        if (text.size() > MAX_UNIT_BYTES || sbrt::printable(text) != text)
            G_fatal_error(_("unit=%s: a unit is at most %zu bytes of printable text "
                            "(unit=none removes it)"),
                          sbrt::printable(sbrt::fit_bytes(unit, 80)).c_str(), MAX_UNIT_BYTES);
        change.unit = text;
    }
    if (kind) {
        sbrt::ChannelKind k;
        if (!sbrt::parse_channel_kind(kind, k)) // GRASS checks options= first
            G_fatal_error(_("kind=%s is none of %s"), sbrt::printable(kind).c_str(),
                          sbrt::channel_kind_names());
        change.kind = k;
    }
    return change;
}

namespace {

std::string channel_names(const sbrt::PropertyChannels &channels)
{
    std::string names;
    for (const sbrt::ChannelInfo &c : channels.infos())
        names += (names.empty() ? "" : ", ") + sbrt::printable(c.name);
    return names;
}

/// `info` with the change made; a probability is in % (its unit set to
/// "%" where it has none and none is given).
sbrt::ChannelInfo changed(sbrt::ChannelInfo info, const ChannelChange &change,
                          const char *sbrt_name)
{
    const std::string name = sbrt::printable(info.name);
    if (change.kind)
        info.kind = *change.kind;
    if (change.unit)
        info.unit = *change.unit;
    else if (info.unit.empty() && (info.known_kind() == sbrt::ChannelKind::probability ||
                                   info.known_kind() == sbrt::ChannelKind::percentage))
        info.unit = "%";
    if (info.known_kind() == sbrt::ChannelKind::probability && info.unit != "%")
        G_fatal_error(_("Channel '%s' of SBRT <%s> would be a probability in '%s': a "
                        "probability is in %% (give unit=%% with kind=probability, or "
                        "another kind=)"),
                      name.c_str(), sbrt_name, sbrt::printable(info.unit).c_str());
    return info;
}

} // namespace

std::vector<sbrt::ChannelInfo> changed_channels(const sbrt::PropertyChannels *channels,
                                                const ChannelChange &change,
                                                const char *sbrt_name)
{
    if (!channels)
        G_fatal_error(_("SBRT <%s> has no property channels: channel= needs an SBRT "
                        "imported with r3.sbrt.convert properties="),
                      sbrt_name);
    std::vector<sbrt::ChannelInfo> infos = channels->infos();
    for (const std::string &name : change.names) {
        const int index = channels->find(name);
        if (index < 0)
            G_fatal_error(_("SBRT <%s> has no channel '%s' (its channels: %s)"), sbrt_name,
                          sbrt::printable(name).c_str(), channel_names(*channels).c_str());
        sbrt::ChannelInfo &info = infos[size_t(index)];
        info = changed(info, change, sbrt_name);
        G_message(_("Channel '%s': %s%s%s"), sbrt::printable(name).c_str(),
                  sbrt::channel_kind_name(info.known_kind()), info.unit.empty() ? "" : " in ",
                  sbrt::printable(info.unit).c_str());
    }
    return infos;
}
