/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The intervals of a model, held compact where that is exact:
 *            4 bytes an interval (u16 material index, u16 top) for models
 *            whose tops are voxel boundaries, else 8 (u32 material, f32
 *            top), owned or a view of a stacks file mapped into memory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_INTERVAL_ARRAY_HPP
#define SBRT_INTERVAL_ARRAY_HPP

#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "util/unfilled_allocator.hpp"

namespace sbrt {

/// \brief One interval of a stack: it ends at `top` (local units) and starts
/// at the previous interval's top, or at 0 for the first one.
struct Interval {
    uint32_t material;
    float top;
};

/// \brief An interval whose top is a voxel boundary (an integer local
/// height up to 65535): exact in half the bytes. Same field names as
/// Interval, so that code templated on the record reads both.
struct CompactInterval {
    uint16_t material;
    uint16_t top;
};
static_assert(sizeof(CompactInterval) == 4, "4 bytes an interval");

/// The intervals of a model, every cell's stack in turn: written by whoever
/// makes them, never zero-filled first (a model's largest array).
using Intervals = std::vector<Interval, UnfilledAllocator<Interval>>;
using CompactIntervals = std::vector<CompactInterval, UnfilledAllocator<CompactInterval>>;

/// An interval ending at voxel boundary `top`, as a Record (Interval or
/// CompactInterval; the caller knows the compact one holds it).
template <typename Record>
Record voxel_interval(uint32_t material, uint32_t top)
{
    if constexpr (std::is_same_v<Record, CompactInterval>)
        return {uint16_t(material), uint16_t(top)};
    else
        return {material, float(top)};
}

/// The record a visit() pointer points to (CompactInterval or Interval).
template <typename Pointer>
using RecordOf = std::remove_const_t<std::remove_pointer_t<Pointer>>;

/// Whether voxel models of `depths` layers fit CompactIntervals (every
/// material index does: at most 65535).
inline bool voxel_tops_fit_compact(int depths) { return depths <= 0xffff; }

/// Whether `iv` is held exactly by a CompactInterval.
inline bool fits_compact(const Interval &iv)
{
    return iv.material <= UINT16_MAX && iv.top >= 0 && iv.top <= float(UINT16_MAX) &&
           float(uint16_t(iv.top)) == iv.top;
}

/// \brief Read-only intervals: compact or wide, owned or a view that keeps
/// alive what holds its memory (`keep`: the mapped file). Copies share the
/// records (they are never written after construction): a model copied
/// for a scene costs its index, not its intervals.
class IntervalArray {
public:
    IntervalArray() = default;
    IntervalArray(Intervals owned)
        : IntervalArray(std::make_shared<const Intervals>(std::move(owned)))
    {
    }
    IntervalArray(CompactIntervals owned)
    {
        auto shared = std::make_shared<const CompactIntervals>(std::move(owned));
        compact_view_ = shared->data();
        size_ = shared->size();
        keep_ = std::move(shared);
        is_compact_ = true;
    }
    IntervalArray(std::shared_ptr<const void> keep, const Interval *data, size_t size)
        : keep_(std::move(keep)), view_(data), size_(size)
    {
    }
    /// Compact where every interval fits (the wide array is released
    /// first where it does not need to be kept), else `wide` as it is.
    static IntervalArray packed(Intervals wide);
    /// This array packed where it owns wide intervals that all fit; a
    /// view (the mapped file, no copy) or a compact array as it is.
    IntervalArray packed() &&;

    size_t size() const { return size_; }
    bool empty() const { return size() == 0; }
    /// Whether the intervals are 4-byte CompactIntervals.
    bool is_compact() const { return is_compact_; }
    /// The records, of the kind held (the other is null).
    const CompactInterval *compact_data() const
    {
        return is_compact_ ? compact_view_ : nullptr;
    }
    const Interval *wide_data() const { return is_compact_ ? nullptr : view_; }
    /// Interval i, widened where held compact.
    Interval operator[](size_t i) const
    {
        if (is_compact_)
            return {compact_view_[i].material, float(compact_view_[i].top)};
        return view_[i];
    }
    /// Bytes per interval in memory: 4 compact, 8 wide.
    unsigned record_bytes() const { return is_compact_ ? 4 : 8; }
    /// Whether the intervals are a view of memory held elsewhere (a
    /// mapped file), not records of their own.
    bool is_view() const { return keep_ != nullptr && !owned_wide_ && !is_compact_; }

    /// Calls f with the records' first pointer (const CompactInterval * or
    /// const Interval *): hot loops are compiled once per kind.
    template <typename F>
    decltype(auto) visit(F &&f) const
    {
        if (is_compact_)
            return f(compact_view_);
        return f(view_);
    }

private:
    explicit IntervalArray(std::shared_ptr<const Intervals> owned)
        : owned_wide_(owned), view_(owned->data()), size_(owned->size())
    {
        keep_ = std::move(owned);
    }

    /// what holds the records: owned arrays (shared by copies) or the file
    std::shared_ptr<const void> keep_;
    /// the owned wide records, where these are they (packed() reads them)
    std::shared_ptr<const Intervals> owned_wide_;
    const Interval *view_ = nullptr;
    const CompactInterval *compact_view_ = nullptr;
    size_t size_ = 0;
    bool is_compact_ = false;
};

} // namespace sbrt

#endif
