/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The intervals of a model: an array of its own (builders,
 *            hidden strata, pruning) or a view of the stacks file mapped
 *            into memory (a render reads the file with no second copy)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_INTERVAL_ARRAY_HPP
#define SBRT_INTERVAL_ARRAY_HPP

#include <cstdint>
#include <memory>
#include <vector>

#include "unfilled_allocator.hpp"

namespace sbrt {

/// \brief One interval of a stack: it ends at `top` (local units) and starts
/// at the previous interval's top, or at 0 for the first one.
struct Interval {
    uint32_t material;
    float top;
};

/// The intervals of a model, every cell's stack in turn: written by whoever
/// makes them, never zero-filled first (a model's largest array).
using Intervals = std::vector<Interval, UnfilledAllocator<Interval>>;

/// \brief Read-only intervals, owned or viewed. A view keeps alive what
/// holds its memory (`keep`: the mapped file); copies share it.
class IntervalArray {
public:
    IntervalArray() = default;
    IntervalArray(Intervals owned) : owned_(std::move(owned)) {}
    IntervalArray(std::shared_ptr<const void> keep, const Interval *data, size_t size)
        : keep_(std::move(keep)), view_(data), size_(size)
    {
    }

    const Interval *data() const { return keep_ ? view_ : owned_.data(); }
    size_t size() const { return keep_ ? size_ : owned_.size(); }
    bool empty() const { return size() == 0; }
    const Interval &operator[](size_t i) const { return data()[i]; }
    const Interval *begin() const { return data(); }
    const Interval *end() const { return data() + size(); }
    /// Whether the intervals are a view of memory held elsewhere.
    bool is_view() const { return keep_ != nullptr; }

private:
    Intervals owned_;
    std::shared_ptr<const void> keep_;
    const Interval *view_ = nullptr;
    size_t size_ = 0;
};

} // namespace sbrt

#endif
