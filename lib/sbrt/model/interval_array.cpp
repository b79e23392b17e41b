/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Intervals packed to 4 bytes where exact
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/interval_array.hpp"

#include <algorithm>
#include <optional>

namespace sbrt {

namespace {

/// The records packed to 4 bytes, or nothing where one does not fit.
std::optional<CompactIntervals> compacted(const Interval *first, const Interval *last)
{
    if (!std::all_of(first, last, fits_compact))
        return std::nullopt;
    CompactIntervals compact(size_t(last - first));
    for (size_t i = 0; i < compact.size(); ++i)
        compact[i] = voxel_interval<CompactInterval>(first[i].material, uint32_t(first[i].top));
    return compact;
}

} // namespace

IntervalArray IntervalArray::packed(Intervals wide)
{
    std::optional<CompactIntervals> compact = compacted(wide.data(), wide.data() + wide.size());
    if (!compact)
        return IntervalArray(std::move(wide));
    Intervals().swap(wide); // released before the compact array is kept
    return IntervalArray(std::move(*compact));
}

IntervalArray IntervalArray::packed() &&
{
    if (is_compact_ || !owned_wide_)
        return std::move(*this);
    std::optional<CompactIntervals> compact = compacted(view_, view_ + size_);
    if (!compact)
        return std::move(*this);
    return IntervalArray(std::move(*compact));
}

} // namespace sbrt
