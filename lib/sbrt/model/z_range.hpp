/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A height range (local units) of the material in a column or a
 *            node of columns: what empty-space skipping reads
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_Z_RANGE_HPP
#define SBRT_Z_RANGE_HPP

namespace sbrt {

/// \brief z-range (local units) of the material in a column or a node;
/// low > high when it holds nothing to draw.
struct ZRange {
    float low = 1, high = 0;
    bool empty() const { return low > high; }
};

/// The range of the records [first, last) of one stack that `drawn(record)`
/// keeps: from the bottom of the lowest (the top of the record below it, 0
/// for the first) to the top of the highest; empty where none is drawn.
template <typename Record, typename Drawn>
ZRange drawn_range(const Record *first, const Record *last, const Drawn &drawn)
{
    const Record *low = first;
    while (low != last && !drawn(*low))
        ++low;
    if (low == last)
        return {};
    const Record *high = last - 1;
    while (!drawn(*high))
        --high;
    return {low == first ? 0.0f : float((low - 1)->top), float(high->top)};
}

} // namespace sbrt

#endif
