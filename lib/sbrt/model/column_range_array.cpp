/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Column ranges packed compact where every one fits
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/column_range_array.hpp"

#include <algorithm>

namespace sbrt {

ColumnRangeArray ColumnRangeArray::packed(std::vector<ZRange> wide)
{
    if (!std::all_of(wide.begin(), wide.end(), fits_compact_range))
        return ColumnRangeArray(std::move(wide));
    std::vector<CompactRange> compact(wide.size());
    for (size_t i = 0; i < wide.size(); ++i)
        if (!wide[i].empty())
            compact[i] = {uint16_t(wide[i].low), uint16_t(wide[i].high)};
    return ColumnRangeArray(std::move(compact));
}

std::vector<ZRange> ColumnRangeArray::widened_all() const
{
    std::vector<ZRange> all(size_);
    for (size_t i = 0; i < size_; ++i)
        all[i] = (*this)[i];
    return all;
}

} // namespace sbrt
