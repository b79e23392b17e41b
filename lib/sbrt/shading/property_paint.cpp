/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colouring hits by a property
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/property_paint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// The material of voxel `level` of a stack; EMPTY above it.
uint32_t material_at(const Model &model, uint64_t cell, int64_t level)
{
    if (level < 0)
        return EMPTY;
    const StackRange range = model.stack(cell);
    const IntervalArray &intervals = model.intervals();
    for (uint64_t i = range.begin; i < range.end; ++i) {
        const Interval iv = intervals[i];
        if (double(level) < double(iv.top))
            return iv.material;
    }
    return EMPTY;
}

} // namespace

bool voxel_of_hit(const Model &model, const Hit &hit, HitVoxel &voxel)
{
    if (!hit.is_hit())
        return false;
    const Frame &f = model.frame();
    const double u = (hit.point.x - f.west) / f.ew_res();
    const double v = (f.north - hit.point.y) / f.ns_res(); // rows from the north
    const double z = f.local_z(hit.point.z);
    int64_t col = int64_t(std::floor(u)), row = int64_t(std::floor(v));
    int64_t level = int64_t(std::floor(z));
    switch (hit.face) { // a wall is the face of the cell the ray enters
    case Face::west:
        col = std::lround(u);
        break;
    case Face::east:
        col = std::lround(u) - 1;
        break;
    case Face::north:
        row = std::lround(v);
        break;
    case Face::south:
        row = std::lround(v) - 1;
        break;
    case Face::top:
        level = std::lround(z) - 1;
        break;
    case Face::bottom:
        level = std::lround(z);
        break;
    default:
        break;
    }
    if (row < 0 || row >= f.rows || col < 0 || col >= f.cols)
        return false;
    const uint64_t cell = model.cell_index(int(row), int(col));
    // a height on an interval's end (a voxel boundary, where the height is
    // whole, or within float's reach of it for a GPU's hits) may lie on
    // either voxel: the one of the hit's interval. A top
    // or bottom face names its voxel, and a cell wall at a height inside a
    // voxel is that voxel's: no stack to walk for most hits. Other faces
    // (planes, boreholes, curtains) are checked against the stack.
    const bool wall = hit.face == Face::west || hit.face == Face::east ||
                      hit.face == Face::south || hit.face == Face::north;
    const bool named = hit.face == Face::top || hit.face == Face::bottom ||
                       (wall && std::abs(z - std::round(z)) > 1e-4);
    if (!named && material_at(model, cell, level) != hit.material) {
        if (material_at(model, cell, level - 1) == hit.material)
            --level;
        else if (material_at(model, cell, level + 1) == hit.material)
            ++level;
        else
            return false;
    }
    if (level < 0 || level >= f.depths)
        return false;
    voxel = {cell, uint32_t(level)};
    return true;
}

struct PropertyPaint::SumBlock {
    std::once_flag once;
    std::vector<uint16_t> index; ///< a whole-valued sum: its value's index
    std::vector<double> sums;    ///< other sums
};

namespace {
/// Sum indices that are no index: no value, and a value outside the
/// file's stated range (not trusted: it is summed again at the hit).
constexpr uint16_t NO_SUM = 0xffff, SUM_OUTSIDE = 0xfffe;
} // namespace

PropertyPaint::~PropertyPaint() = default;

PropertyPaint::PropertyPaint(const Model &model,
                             std::shared_ptr<const PropertyChannels> channels,
                             std::vector<size_t> summed, ColorRamp ramp,
                             std::array<uint8_t, 3> no_value)
    : model_(model), channels_(std::move(channels)), summed_(std::move(summed)),
      ramp_(std::move(ramp)), no_value_(no_value[0], no_value[1], no_value[2])
{
    if (!channels_ || summed_.empty())
        fail("a property view without channels");
    for (size_t c : summed_)
        if (c >= channels_->size())
            fail("a property view of channel ", c, " of ", channels_->size());
    // a sum of integer values (GeoTOP's percentages) takes few values: the
    // ramp's colour of each, looked up by index instead of searched
    whole_ = whole_values(*channels_, summed_, MAX_COLOR_TABLE);
    table_.resize(whole_.count);
    for (size_t k = 0; k < table_.size(); ++k)
        table_[k] = ramp_.at(whole_.low + double(k));
}

void PropertyPaint::keep_block_sums()
{
    if (summed_.size() > 1 && !sums_)
        sums_ = std::make_unique<SumBlock[]>(channels_->blocks());
}

const PropertyPaint::SumBlock &PropertyPaint::block_sums(size_t block) const
{
    SumBlock &b = sums_[block];
    std::call_once(b.once, [&] {
        std::vector<ChannelValues> values;
        for (size_t c : summed_)
            values.push_back(channels_->block_values(c, block));
        const size_t n = values[0].size();
        // a whole-valued sum as the index of its value: 2 bytes a voxel
        const bool indexed = whole_.count > 0 && whole_.count < SUM_OUTSIDE;
        if (indexed)
            b.index.resize(n);
        else
            b.sums.resize(n);
        for (size_t i = 0; i < n; ++i) {
            double sum;
            if (!sum_at(*channels_, summed_, values.data(), i, sum))
                sum = std::numeric_limits<double>::quiet_NaN(); // a fill
            if (!indexed) {
                b.sums[i] = sum;
                continue;
            }
            const int64_t k = std::isnan(sum) ? -1 : whole_.index(sum);
            b.index[i] = std::isnan(sum) ? NO_SUM : k < 0 ? SUM_OUTSIDE : uint16_t(k);
        }
    });
    return b;
}

WholeValues whole_values(const PropertyChannels &channels, const std::vector<size_t> &summed,
                         size_t most)
{
    double low = 0, high = 0;
    for (size_t c : summed) {
        const ChannelInfo &info = channels.info(c);
        if (!info.integer || info.scale != std::round(info.scale) ||
            info.offset != std::round(info.offset) || !std::isfinite(info.min) ||
            !std::isfinite(info.max))
            return {};
        const double a = info.physical(float(info.min)), b = info.physical(float(info.max));
        low += std::min(a, b);
        high += std::max(a, b);
    }
    if (!(high - low < double(most)))
        return {};
    return {low, size_t(high - low) + 1};
}

bool sum_range(const PropertyChannels &channels, const std::vector<size_t> &summed,
               double &low, double &high)
{
    if (summed.size() == 1) { // its stated range (0 to 0 where it has no value)
        const ChannelInfo &info = channels.info(summed[0]);
        const double a = info.physical(float(info.min)), b = info.physical(float(info.max));
        low = std::min(a, b);
        high = std::max(a, b);
        return info.valid > 0;
    }
    // the blocks that hold values: those of the cells with a span (a model
    // read for an area has none elsewhere, and its blocks are not decoded)
    std::vector<bool> holds(channels.blocks(), false);
    for (uint64_t cell = 0; cell < channels.cells(); ++cell)
        if (channels.span(cell).size() > 0)
            holds[channels.block_of(cell)] = true;
    low = std::numeric_limits<double>::infinity();
    high = -low;
    std::vector<ChannelValues> values(summed.size());
    for (size_t b = 0; b < holds.size(); ++b) {
        if (!holds[b])
            continue;
        for (size_t k = 0; k < summed.size(); ++k)
            values[k] = channels.block_values(summed[k], b);
        for (size_t i = 0, n = values[0].size(); i < n; ++i) {
            double sum;
            if (sum_at(channels, summed, values.data(), i, sum) && !std::isnan(sum)) {
                low = std::min(low, sum);
                high = std::max(high, sum);
            }
        }
    }
    if (low <= high)
        return true;
    low = high = 0;
    return false;
}

bool property_at_hit(const Model &model, const PropertyChannels &channels,
                     const std::vector<size_t> &summed, const Hit &hit, double &out)
{
    HitVoxel voxel;
    return voxel_of_hit(model, hit, voxel) && property_at_voxel(channels, summed, voxel, out);
}

bool sum_at(const PropertyChannels &channels, const std::vector<size_t> &summed,
            const ChannelValues *values, size_t i, double &out)
{
    double sum = 0;
    for (size_t k = 0; k < summed.size(); ++k) {
        const float raw = values[k][i];
        const ChannelInfo &info = channels.info(summed[k]);
        if (info.is_fill(raw))
            return false;
        sum += info.physical(raw);
    }
    out = sum;
    return true;
}

bool property_at_voxel(const PropertyChannels &channels, const std::vector<size_t> &summed,
                       const HitVoxel &voxel, double &out)
{
    double sum = 0;
    for (size_t c : summed) {
        float raw;
        const ChannelInfo &info = channels.info(c);
        if (!channels.value(c, voxel.cell, voxel.level, raw) || info.is_fill(raw))
            return false;
        sum += info.physical(raw);
    }
    out = sum;
    return true;
}

bool PropertyPaint::value(const Hit &hit, double &out) const
{
    if (!sums_)
        return property_at_hit(model_, *channels_, summed_, hit, out);
    HitVoxel voxel;
    if (!voxel_of_hit(model_, hit, voxel))
        return false;
    const CellSlot &slot = channels_->slot(voxel.cell);
    if (voxel.level < slot.lo || voxel.level >= slot.hi)
        return false;
    const SumBlock &b = block_sums(channels_->block_of(voxel.cell));
    const size_t at = slot.at + (voxel.level - slot.lo);
    if (!b.index.empty()) {
        const uint16_t k = b.index[at];
        if (k == NO_SUM)
            return false;
        if (k == SUM_OUTSIDE)
            return property_at_hit(model_, *channels_, summed_, hit, out);
        out = whole_.low + double(k);
        return true;
    }
    if (std::isnan(b.sums[at]))
        return false;
    out = b.sums[at];
    return true;
}

UncertaintyFade::UncertaintyFade(const Model &model,
                                 std::shared_ptr<const PropertyChannels> channels,
                                 size_t channel, double low, double high)
    : model_(model), channels_(std::move(channels)), channel_{channel}, low_(low),
      high_(high)
{
    if (!channels_ || channel >= channels_->size())
        fail("an uncertainty fade without its channel");
    if (!(high > low))
        fail("an uncertainty fade from ", low, " to ", high, ": the high end must be "
             "above the low one");
    whole_ = whole_values(*channels_, channel_, MAX_ENTRIES);
}

bool UncertaintyFade::value(const Hit &hit, double &out) const
{
    return property_at_hit(model_, *channels_, channel_, hit, out);
}

bool UncertaintyFade::voxel_value(const HitVoxel &voxel, double &out) const
{
    return property_at_voxel(*channels_, channel_, voxel, out);
}

glm::dvec3 UncertaintyFade::faded(const glm::dvec3 &color, double value) const
{
    // Rec. 709 luminance: the grey the colour fades to
    const double grey = 0.2126 * color.x + 0.7152 * color.y + 0.0722 * color.z;
    return color + share(value) * (glm::dvec3(grey) - color);
}

std::vector<glm::dvec3> UncertaintyFade::entry_colors(const glm::dvec3 &base) const
{
    std::vector<glm::dvec3> entries;
    entries.reserve(whole_.count + 1);
    for (size_t k = 0; k < whole_.count; ++k)
        entries.push_back(faded(base, whole_.low + double(k)));
    entries.push_back(base);
    return entries;
}

double UncertaintyFade::share(double value) const
{
    return std::clamp((value - low_) / (high_ - low_), 0.0, 1.0);
}

glm::dvec3 UncertaintyFade::apply(const Hit &hit, glm::dvec3 color) const
{
    double v;
    return value(hit, v) ? faded(color, v) : color;
}

std::vector<glm::dvec3> PropertyPaint::entry_colors() const
{
    std::vector<glm::dvec3> entries = table_;
    entries.push_back(no_value_);
    return entries;
}

glm::dvec3 PropertyPaint::color(const Hit &hit) const
{
    double v;
    if (!value(hit, v))
        return no_value_;
    // the table where it holds v (a file's stated range is not trusted)
    const int64_t k = whole_.index(v);
    return k >= 0 ? table_[size_t(k)] : ramp_.at(v);
}

} // namespace sbrt
