/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Column ranges widened, for code that is not hot
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/column_range_array.hpp"

namespace sbrt {

std::vector<ZRange> ColumnRangeArray::widened_all() const
{
    std::vector<ZRange> all(size());
    for (size_t i = 0; i < all.size(); ++i)
        all[i] = (*this)[i];
    return all;
}

} // namespace sbrt
