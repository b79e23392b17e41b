/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The channels of property= and their colour ramp
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "property_colors.hpp"

#include <unistd.h>

#include <algorithm>

#include "grass_color_rules.hpp"
#include "shading/property_paint.hpp"
#include "request_error.hpp"

std::vector<size_t> property_channels(const RenderRequest &request,
                                      const sbrt::PropertyChannels *channels)
{
    if (!channels)
        bad_request(_("SBRT <%s> has no property channels: property=%s needs an SBRT "
                      "imported with properties= (r3.sbrt.convert file=... properties=...)"),
                    request.input.c_str(), request.property_title().c_str());
    std::string names;
    for (const sbrt::ChannelInfo &c : channels->infos())
        names += (names.empty() ? "" : ", ") + c.name;
    std::vector<size_t> summed;
    for (const std::string &name : request.property) {
        const int index = channels->find(name);
        if (index < 0)
            bad_request(_("SBRT <%s> has no property channel '%s'; it has: %s"),
                        request.input.c_str(), name.c_str(), names.c_str());
        if (std::find(summed.begin(), summed.end(), size_t(index)) != summed.end())
            bad_request(_("property=%s names '%s' twice"),
                        request.property_title().c_str(), name.c_str());
        summed.push_back(size_t(index));
    }
    const sbrt::ChannelInfo &first = channels->info(summed[0]);
    for (size_t c : summed) {
        const sbrt::ChannelInfo &info = channels->info(c);
        if (info.unit != first.unit)
            bad_request(_("property=%s adds channels of different units ('%s' in %s, "
                          "'%s' in %s): a sum needs one unit"),
                        request.property_title().c_str(), first.name.c_str(),
                        first.unit.empty() ? "none" : first.unit.c_str(),
                        info.name.c_str(), info.unit.empty() ? "none" : info.unit.c_str());
    }
    return summed;
}

bool probability_family(const sbrt::PropertyChannels &channels,
                        const std::vector<size_t> &summed)
{
    for (size_t c : summed)
        if (channels.info(c).known_kind() != sbrt::ChannelKind::probability)
            return false;
    return !summed.empty();
}

std::pair<double, double> property_range(const sbrt::PropertyChannels &channels,
                                         const std::vector<size_t> &summed)
{
    if (probability_family(channels, summed))
        return {0.0, 100.0};
    double low = 0, high = 0;
    if (!sbrt::sum_range(channels, summed, low, high))
        low = high = 0; // no value anywhere: every hit the no-value colour
    if (!(high > low))
        high = low + 1; // one value: a ramp all the same
    return {low, high};
}

std::string property_unit(const sbrt::PropertyChannels &channels,
                          const std::vector<size_t> &summed)
{
    if (probability_family(channels, summed))
        return "%";
    return summed.empty() ? std::string() : channels.info(summed[0]).unit;
}

sbrt::ColorRamp property_ramp(const std::string &table, double low, double high)
{
    GrassColors grass_colors;
    struct Colors &colors = *grass_colors.get();
    const bool is_file = table.find('/') != std::string::npos || access(table.c_str(), R_OK) == 0;
    if (is_file) // read and checked by us, never by GRASS's reader
        set_grass_colors(
            sbrt::read_color_rules_file(table, "property_color=" + table), low, high,
            &colors);
    else {
        if (!G_find_color_rule(table.c_str()))
            bad_request(_("property_color=%s is neither a GRASS colour table (e.g. "
                          "viridis, magma, bcyr, grey; see r.colors) nor a rules file"),
                        table.c_str());
        Rast_make_fp_colors(&colors, table.c_str(), low, high);
    }
    std::vector<sbrt::ColorRamp::Rule> rules;
    for (int i = 0, n = Rast_colors_count(&colors); i < n; ++i) {
        DCELL v1, v2;
        unsigned char r1, g1, b1, r2, g2, b2;
        if (Rast_get_fp_color_rule(&v1, &r1, &g1, &b1, &v2, &r2, &g2, &b2, &colors, i))
            continue;
        rules.push_back({{v1, {r1, g1, b1}}, {v2, {r2, g2, b2}}});
    }
    if (rules.empty())
        bad_request(_("property_color=%s gives no colour rules"), table.c_str());
    return sbrt::ColorRamp(std::move(rules));
}
