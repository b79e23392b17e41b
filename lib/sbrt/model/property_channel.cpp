/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Property channels: types, figures, the solid span of a column
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/property_channel.hpp"

#include <algorithm>

#include "util/error.hpp"

namespace sbrt {

const char *channel_type_name(ChannelType type)
{
    switch (type) {
    case ChannelType::uint8:
        return "u8";
    case ChannelType::int8:
        return "i8";
    case ChannelType::uint16:
        return "u16";
    case ChannelType::int16:
        return "i16";
    case ChannelType::float32:
        break;
    }
    return "f32";
}

unsigned channel_type_bytes(ChannelType type)
{
    switch (type) {
    case ChannelType::uint8:
    case ChannelType::int8:
        return 1;
    case ChannelType::uint16:
    case ChannelType::int16:
        return 2;
    case ChannelType::float32:
        break;
    }
    return 4;
}

const char *channel_kind_name(ChannelKind kind)
{
    switch (kind) {
    case ChannelKind::probability:
        return "probability";
    case ChannelKind::percentage:
        return "percentage";
    case ChannelKind::uncertainty:
        return "uncertainty";
    case ChannelKind::other:
        return "other";
    case ChannelKind::unset:
        break;
    }
    return "";
}

const char *channel_kind_names()
{
    return "probability,percentage,uncertainty,other";
}

bool parse_channel_kind(const std::string &name, ChannelKind &kind)
{
    for (uint8_t k = 1; k <= LAST_CHANNEL_KIND; ++k)
        if (name == channel_kind_name(ChannelKind(k))) {
            kind = ChannelKind(k);
            return true;
        }
    return false;
}

ChannelKind kind_of_unit(const std::string &unit)
{
    return unit == "%" ? ChannelKind::probability : ChannelKind::other;
}

ChannelType ChannelInfo::type() const
{
    if (!integer)
        return ChannelType::float32;
    double lo = valid ? min : 0, hi = valid ? max : 0;
    if (has_fill) {
        lo = std::min(lo, double(fill));
        hi = std::max(hi, double(fill));
    }
    if (lo >= 0 && hi <= 255)
        return ChannelType::uint8;
    if (lo >= -128 && hi <= 127)
        return ChannelType::int8;
    if (lo >= 0 && hi <= 65535)
        return ChannelType::uint16;
    if (lo >= -32768 && hi <= 32767)
        return ChannelType::int16;
    return ChannelType::float32;
}

namespace {

uint32_t voxel_level(float top, uint64_t cell)
{
    if (!(top >= 0) || top > float(UINT32_MAX) || float(uint32_t(top)) != top)
        fail("cell ", cell, ": top ", top,
             " is not a voxel boundary (property channels need a model made "
             "of voxels, not of continuous horizons)");
    return uint32_t(top);
}

} // namespace

ColumnSpan solid_span(const Model &model, uint64_t cell)
{
    const StackRange range = model.stack(cell);
    if (range.size() == 0)
        return {};
    const IntervalArray &intervals = model.intervals();
    ColumnSpan span;
    const Interval first = intervals[range.begin];
    if (first.material == EMPTY && range.size() > 1)
        span.lo = voxel_level(first.top, cell);
    span.hi = voxel_level(intervals[range.end - 1].top, cell);
    return span;
}

bool has_voxel_tops(const Model &model)
{
    return model.intervals().visit([&](const auto *records) {
        for (size_t i = 0, n = model.intervals().size(); i < n; ++i) {
            const float top = float(records[i].top);
            if (!(top >= 0) || float(uint32_t(top)) != top)
                return false;
        }
        return true;
    });
}

} // namespace sbrt
