/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Intervals packed to 4 bytes where exact
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/interval_array.hpp"

#include <algorithm>

namespace sbrt {

IntervalArray IntervalArray::packed(Intervals wide)
{
    if (!std::all_of(wide.begin(), wide.end(), fits_compact))
        return IntervalArray(std::move(wide));
    CompactIntervals compact(wide.size());
    for (size_t i = 0; i < wide.size(); ++i)
        compact[i] = voxel_interval<CompactInterval>(wide[i].material, uint32_t(wide[i].top));
    return IntervalArray(std::move(compact));
}

IntervalArray IntervalArray::packed() &&
{
    if (is_compact_ || keep_)
        return std::move(*this);
    return packed(std::move(wide_));
}

} // namespace sbrt
