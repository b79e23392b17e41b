/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colouring hits by a property (issue 29): the value of a
 *            channel, or the sum of several, at the voxel a ray hits,
 *            through a colour ramp
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PROPERTY_PAINT_HPP
#define SBRT_PROPERTY_PAINT_HPP

#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "format/channels_file.hpp"
#include "shading/color_ramp.hpp"
#include "tracing/tracer.hpp"

namespace sbrt {

/// \brief The voxel of a model a hit lies on.
struct HitVoxel {
    uint64_t cell = 0;
    uint32_t level = 0;
};

/// The voxel of `model` (as read: the one the channels belong to) that
/// `hit` lies on: the cell whose face or inside it is (a wall between two
/// cells belongs to the cell the ray enters), the level of the hit's
/// interval at the hit's height (a top face is its voxel below, a bottom
/// face its voxel above). False where the hit is no hit of the model.
bool voxel_of_hit(const Model &model, const Hit &hit, HitVoxel &voxel);

/// The sum of `summed` channels (as meant) at the voxel of `hit`; false
/// where the hit has no voxel, lies outside the spans or meets a fill.
bool property_at_hit(const Model &model, const PropertyChannels &channels,
                     const std::vector<size_t> &summed, const Hit &hit, double &out);
/// The same at `voxel`.
bool property_at_voxel(const PropertyChannels &channels, const std::vector<size_t> &summed,
                       const HitVoxel &voxel, double &out);

/// The sum of `summed` channels at position `i` of `values` (one view per
/// summed channel, in its order, of the same voxels), as property_at_voxel
/// makes it: values as meant, added in the order of `summed`; false where
/// one is a fill.
bool sum_at(const PropertyChannels &channels, const std::vector<size_t> &summed,
            const ChannelValues *values, size_t i, double &out);

/// The least and greatest sum of `summed` channels over every voxel that
/// has one (fills skipped): the range of the values the property takes,
/// not the sum of the channels' ranges. One channel's is its stated range;
/// a sum decodes every block that holds values. False where no voxel has a
/// value.
bool sum_range(const PropertyChannels &channels, const std::vector<size_t> &summed,
               double &low, double &high);

/// \brief The whole numbers low, low + 1, ..., low + count - 1: the values
/// a property takes where they are few (GeoTOP's percentages), so that a
/// colour per value can be made once; count 0 where they are not.
struct WholeValues {
    double low = 0;
    size_t count = 0;
    /// The index of `v` among them, or -1 where it is none of them (a
    /// file's stated range is not trusted).
    int64_t index(double v) const
    {
        const double k = v - low;
        return k >= 0 && k < double(count) && k == std::floor(k) ? int64_t(k) : -1;
    }
};

/// The values the sum of `summed` channels can take, where each holds
/// integers with a whole scale and offset and they are fewer than `most`.
WholeValues whole_values(const PropertyChannels &channels, const std::vector<size_t> &summed,
                         size_t most);

/// \brief Class colours faded by an uncertainty channel: a voxel whose
/// value is `low` or less keeps its colour, one at `high` or more is grey
/// (the colour's own luminance), linearly between.
class UncertaintyFade {
public:
    UncertaintyFade(const Model &model, std::shared_ptr<const PropertyChannels> channels,
                    size_t channel, double low, double high);
    /// `color` (0..255) of `hit` faded by the uncertainty at its voxel
    /// (unchanged where it has none).
    glm::dvec3 apply(const Hit &hit, glm::dvec3 color) const;
    /// The share of grey, 0..1, of an uncertainty value.
    double share(double value) const;
    /// The uncertainty at `hit`'s voxel; false where it has none.
    bool value(const Hit &hit, double &out) const;
    /// The uncertainty at `voxel`; false where it has none.
    bool voxel_value(const HitVoxel &voxel, double &out) const;
    const PropertyChannels &channels() const { return *channels_; }
    /// `color` faded by uncertainty `value`.
    glm::dvec3 faded(const glm::dvec3 &color, double value) const;
    double low() const { return low_; }
    double high() const { return high_; }
    size_t channel() const { return channel_[0]; }
    /// The uncertainty's values where they are few whole numbers (at most
    /// MAX_ENTRIES: GeoTOP's onz_lk 0..100); count 0 otherwise.
    static constexpr size_t MAX_ENTRIES = 4096;
    const WholeValues &whole() const { return whole_; }
    /// `base` faded by each of whole()'s values, then `base` itself (the
    /// colour of a voxel without a value): the entries a table holds.
    std::vector<glm::dvec3> entry_colors(const glm::dvec3 &base) const;

private:
    const Model &model_;
    std::shared_ptr<const PropertyChannels> channels_;
    std::vector<size_t> channel_;
    double low_, high_;
    WholeValues whole_;
};

/// \brief A property shown on the model's hits.
class PropertyPaint {
public:
    /// `model` as read (before strata are hidden), its `channels`, the
    /// channels to add (their values as meant: stored * scale + offset),
    /// the ramp, and the colour of hits without a value (outside the
    /// channels' spans or a fill in any of them).
    PropertyPaint(const Model &model, std::shared_ptr<const PropertyChannels> channels,
                  std::vector<size_t> summed, ColorRamp ramp,
                  std::array<uint8_t, 3> no_value = {190, 190, 190});
    ~PropertyPaint();

    /// The property at `hit`; false where it has none.
    bool value(const Hit &hit, double &out) const;
    /// The property at `voxel`; false where it has none.
    bool voxel_value(const HitVoxel &voxel, double &out) const
    {
        return property_at_voxel(*channels_, summed_, voxel, out);
    }
    /// From now on a sum is made for a whole block where a hit first needs
    /// one of its values, and kept: later hits read one array instead of
    /// one per channel. Pays where blocks are seen again (a session of
    /// several frames), not in one frame, whose hits read few of a block's
    /// values; not to be called while a frame is shaded.
    void keep_block_sums();
    /// The surface colour of `hit` (0..255) before lighting.
    glm::dvec3 color(const Hit &hit) const;

    /// The values of an integer-valued sum (count 0 for other properties)
    /// and the ramp's colour of each, in their order.
    const WholeValues &whole() const { return whole_; }
    const std::vector<glm::dvec3> &table() const { return table_; }
    /// The table, then the no-value colour: the entries a table of
    /// whole() holds.
    std::vector<glm::dvec3> entry_colors() const;
    /// Hits without a value take this colour.
    const glm::dvec3 &no_value() const { return no_value_; }
    const ColorRamp &ramp() const { return ramp_; }
    const PropertyChannels &channels() const { return *channels_; }
    const std::vector<size_t> &summed() const { return summed_; }

    /// Most entries of the colour table of an integer-valued property.
    static constexpr size_t MAX_COLOR_TABLE = 1 << 16;

private:
    struct SumBlock;
    /// The sums of `block`'s voxels (made once, by whichever thread needs
    /// it first).
    const SumBlock &block_sums(size_t block) const;

    const Model &model_;
    std::shared_ptr<const PropertyChannels> channels_;
    std::vector<size_t> summed_;
    ColorRamp ramp_;
    glm::dvec3 no_value_;
    /// the ramp at each of whole_'s values (empty without them)
    WholeValues whole_;
    std::vector<glm::dvec3> table_;
    /// a sum's values block by block: a hit reads one array, not one per
    /// channel (each a cache miss on a model larger than the cache)
    std::unique_ptr<SumBlock[]> sums_;
};

} // namespace sbrt

#endif
