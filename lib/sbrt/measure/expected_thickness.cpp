/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The expected thickness of a column from probability channels
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/expected_thickness.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "util/error.hpp"

namespace sbrt {

std::vector<size_t> probability_channels(const PropertyChannels &channels,
                                         const std::string &probability)
{
    std::vector<size_t> out;
    std::stringstream parts(probability);
    std::string name;
    while (std::getline(parts, name, '+')) {
        name.erase(0, name.find_first_not_of(" \t"));
        name.erase(name.find_last_not_of(" \t") + 1);
        const int index = channels.find(name);
        if (index < 0) {
            std::string names;
            for (const ChannelInfo &c : channels.infos())
                names += (names.empty() ? "" : ", ") + c.name;
            fail("probability=", probability, ": no channel '", name, "'; the SBRT has: ",
                 names);
        }
        if (std::find(out.begin(), out.end(), size_t(index)) != out.end())
            fail("probability=", probability, ": channel '", name, "' is named twice");
        const ChannelInfo &info = channels.info(size_t(index));
        // what the channel is (issue 51): its kind, set on import (unit
        // "%" or a survey preset) or by r3.sbrt.support, not the unit alone
        if (info.known_kind() != ChannelKind::probability)
            fail("probability=", probability, ": channel '", name, "' is in '", info.unit,
                 "' and of kind ", channel_kind_name(info.known_kind()),
                 ", not a probability in %; where it is one, say so: r3.sbrt.support "
                 "channel=", name, " unit=% kind=probability");
        out.push_back(size_t(index));
    }
    if (out.empty())
        fail("probability= names no channel");
    return out;
}

double expected_thickness(const PropertyChannels &channels, const std::vector<size_t> &summed,
                          uint64_t cell, double voxel_height)
{
    const ColumnSpan span = channels.span(cell);
    if (span.size() == 0)
        return NAN;
    std::vector<ChannelValues> columns;
    for (const size_t c : summed)
        columns.push_back(channels.column(c, cell));
    double percent = 0; // the sum of p over the voxels with a value
    bool any = false;
    for (uint32_t v = 0; v < span.size(); ++v) {
        double p = 0;
        bool has = true;
        for (size_t k = 0; k < summed.size() && has; ++k) {
            const ChannelInfo &info = channels.info(summed[k]);
            const float raw = columns[k][v];
            has = !info.is_fill(raw);
            p += info.physical(raw);
        }
        if (has) {
            percent += p;
            any = true;
        }
    }
    return any ? percent / 100.0 * voxel_height : NAN;
}

std::vector<ExpectedVolume> expected_volumes(const Model &model,
                                             const PropertyChannels &channels,
                                             const std::vector<size_t> &summed,
                                             const std::vector<int32_t> &cell_zones, int zones)
{
    const Frame &frame = model.frame();
    const double area = frame.ew_res() * frame.ns_res();
    std::vector<ExpectedVolume> out(size_t(std::max(0, zones)));
    for (uint64_t cell = 0; cell < cell_zones.size(); ++cell) {
        const int32_t zone = cell_zones[cell];
        if (zone < 0 || zone >= zones)
            continue;
        const double e = expected_thickness(channels, summed, cell, frame.tb_res());
        if (std::isnan(e))
            continue;
        out[size_t(zone)].volume += e * area;
        if (e > 0)
            ++out[size_t(zone)].cells;
    }
    return out;
}

} // namespace sbrt
