/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Property channels (issue 29): named per-voxel values beside
 *            the classes (probabilities, uncertainties), carried per
 *            column over the column's solid span
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PROPERTY_CHANNEL_HPP
#define SBRT_PROPERTY_CHANNEL_HPP

#include <cmath>
#include <cstdint>
#include <string>

#include "model/model.hpp"

namespace sbrt {

/// The types a channel's values are held exactly in, smallest first.
enum class ChannelType : uint8_t { uint8, int8, uint16, int16, float32 };
/// "u8", "i8", "u16", "i16", "f32".
const char *channel_type_name(ChannelType type);
/// Bytes of one value of `type`.
unsigned channel_type_bytes(ChannelType type);

/// \brief What a channel's values are (issue 51), so that a measure knows
/// which it may take: the expected thickness sums probabilities only.
/// Stored as a byte (channels file 1.1); `unset` only before writing: the
/// writer stores what the unit says (kind_of_unit), as files before 1.1
/// are read.
enum class ChannelKind : uint8_t {
    unset = 0,
    probability = 1, ///< a probability in % (0-100), e.g. GeoTOP's kans_*
    percentage = 2,  ///< a share in % that is no probability
    uncertainty = 3, ///< a measure of uncertainty, e.g. GeoTOP's onz_*
    other = 4,       ///< any other quantity
};
/// The largest kind a file may store.
constexpr uint8_t LAST_CHANNEL_KIND = 4;
/// "probability", "percentage", "uncertainty", "other" ("" for unset).
const char *channel_kind_name(ChannelKind kind);
/// Every kind's name, comma-separated (for option lists and messages).
const char *channel_kind_names();
/// The kind called `name` (one of channel_kind_names()), or false.
bool parse_channel_kind(const std::string &name, ChannelKind &kind);
/// The kind a unit says where nothing else does (as before kinds were
/// stored): "%" a probability, anything else other.
ChannelKind kind_of_unit(const std::string &unit);

/// \brief One channel: its name and legend, and figures of its values.
/// Values are raw numbers as the source stores them (float32 holds every
/// value a channel may take exactly); what they mean is raw * scale +
/// offset (CF's scale_factor and add_offset), the fill and NaN mark no
/// value.
struct ChannelInfo {
    std::string name, long_name, unit;
    ChannelKind kind = ChannelKind::unset; ///< as read: never unset
    double scale = 1, offset = 0;
    bool has_fill = false;
    float fill = 0;

    // what the values are, over the solid spans (the writer's figures)
    uint64_t voxels = 0; ///< values stored, fills included
    uint64_t valid = 0;  ///< of them not the fill
    double min = 0, max = 0; ///< of the valid values (0 where none)
    bool integer = true;     ///< every value (fill too) an integer
    uint64_t bytes = 0;      ///< on disk: compressed blocks and block table

    /// Whether `v` is no value: the fill, or NaN (never a value: a 3D
    /// raster of it is null, so counts and views agree with -r).
    bool is_fill(float v) const { return std::isnan(v) || (has_fill && v == fill); }
    double physical(float raw) const { return double(raw) * scale + offset; }
    /// The kind, or where it is unset what the unit says.
    ChannelKind known_kind() const
    {
        return kind == ChannelKind::unset ? kind_of_unit(unit) : kind;
    }
    /// The smallest type that holds every value and the fill exactly.
    ChannelType type() const;
};

/// \brief Voxel levels [lo, hi) of a column that carry channel values: from
/// the bottom of its lowest solid interval to its top (caves inside count;
/// nothing below or above). Empty for an empty column.
struct ColumnSpan {
    uint32_t lo = 0, hi = 0;
    uint32_t size() const { return hi - lo; }
    bool holds(uint32_t level) const { return level >= lo && level < hi; }
};

/// The solid span of a cell's stack; throws sbrt::Error where a top that
/// bounds it is not a voxel boundary (channels need voxel models).
ColumnSpan solid_span(const Model &model, uint64_t cell);

/// Whether every top of the model is a voxel boundary (the models that
/// can carry channels: from voxels, not from continuous horizons).
bool has_voxel_tops(const Model &model);

} // namespace sbrt

#endif
