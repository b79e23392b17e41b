/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Each column's range of material, held compact where that is
 *            exact: 4 bytes a column (u16 low, u16 high) for models whose
 *            tops are voxel boundaries, else 8 (two floats). A paged
 *            model's largest array (60 MB wide in a national model) and
 *            the level 0 its rays read cell by cell
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_RANGE_ARRAY_HPP
#define SBRT_COLUMN_RANGE_ARRAY_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/z_range.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

/// \brief A column's range between voxel boundaries: exact in half the
/// bytes. Empty as ZRange{} is: low 1, high 0 (widened, that is ZRange{}).
struct CompactRange {
    uint16_t low = 1, high = 0;
};
static_assert(sizeof(CompactRange) == 4, "4 bytes a column");

inline ZRange widened(const CompactRange &range) { return {float(range.low), float(range.high)}; }
inline ZRange widened(const ZRange &range) { return range; }

/// Whether `range` is held exactly by a CompactRange (an empty one is).
inline bool fits_compact_range(const ZRange &range)
{
    if (range.empty())
        return true;
    return range.low >= 0 && range.high <= float(UINT16_MAX) &&
           float(uint16_t(range.low)) == range.low && float(uint16_t(range.high)) == range.high;
}

/// Compact ranges, written by whoever makes them (every column), never
/// zero-filled first; huge pages as UnfilledAllocator advises them.
using CompactRanges = std::vector<CompactRange, UnfilledAllocator<CompactRange>>;

/// \brief Read-only column ranges (row by row, row 0 north), compact or
/// wide, read as ZRanges. Moved, never copied (60 MB wide national).
class ColumnRangeArray {
public:
    ColumnRangeArray() = default;
    explicit ColumnRangeArray(std::vector<ZRange> wide) : wide_(std::move(wide)) {}
    explicit ColumnRangeArray(CompactRanges compact)
        : compact_(std::move(compact)), is_compact_(true)
    {
    }
    ColumnRangeArray(ColumnRangeArray &&) = default;
    ColumnRangeArray &operator=(ColumnRangeArray &&) = default;
    ColumnRangeArray(const ColumnRangeArray &) = delete;
    ColumnRangeArray &operator=(const ColumnRangeArray &) = delete;

    size_t size() const { return is_compact_ ? compact_.size() : wide_.size(); }
    bool empty() const { return size() == 0; }
    bool is_compact() const { return is_compact_; }
    /// The records, of the kind held (the other is null).
    const CompactRange *compact_data() const { return is_compact_ ? compact_.data() : nullptr; }
    const ZRange *wide_data() const { return is_compact_ ? nullptr : wide_.data(); }
    /// Column i's range, widened where held compact.
    ZRange operator[](size_t i) const { return is_compact_ ? widened(compact_[i]) : wide_[i]; }
    /// Bytes a column in memory: 4 compact, 8 wide.
    unsigned record_bytes() const { return is_compact_ ? 4 : 8; }
    uint64_t bytes() const { return uint64_t(size()) * record_bytes(); }
    /// Calls f with the records' first pointer (const CompactRange * or
    /// const ZRange *): hot loops are compiled once per kind.
    template <typename F>
    decltype(auto) visit(F &&f) const
    {
        if (is_compact_)
            return f(compact_.data());
        return f(wide_.data());
    }
    /// Every range, wide (for tests and code that is not hot).
    std::vector<ZRange> widened_all() const;

private:
    std::vector<ZRange> wide_;
    CompactRanges compact_;
    bool is_compact_ = false;
};

} // namespace sbrt

#endif
