/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Where each cell's stack lies in the intervals: the count of
 *            every cell (u8, or u16/u32 where a stack is longer) and one
 *            64-bit offset per group of 16 cells: 1.5 bytes a cell for
 *            models whose stacks hold at most 255 intervals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACK_INDEX_HPP
#define SBRT_STACK_INDEX_HPP

#include <cstdint>
#include <cstring>
#include <vector>

#include "util/error.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

/// \brief The intervals [begin, end) of one stack.
struct StackRange {
    uint64_t begin, end;
    uint64_t size() const { return end - begin; }
};

/// \brief Stack counts and group offsets: the start of cell c is the offset
/// of its group (c / 16) plus the counts of the cells before it there.
class StackIndex {
public:
    static constexpr unsigned GROUP = 16;

    StackIndex() = default;
    /// From the size of every stack, in cell order; counts take the
    /// smallest width that holds the longest.
    template <typename Size>
    static StackIndex from_sizes(const Size *sizes, uint64_t cells);
    /// From cells + 1 non-decreasing offsets starting at 0; throws
    /// sbrt::Error where they are not.
    template <typename Offset>
    static StackIndex from_offsets(const Offset *offsets, uint64_t cells);

    uint64_t cells() const { return cells_; }
    /// Intervals of all stacks.
    uint64_t total() const { return total_; }
    uint32_t max_size() const { return max_size_; }
    /// Bytes per count: 1, 2 or 4.
    unsigned count_bytes() const { return count_bytes_; }
    /// Bytes the index takes in memory.
    uint64_t bytes() const
    {
        return counts_.size() + bases_.size() * sizeof(uint64_t);
    }
    /// Bytes an index of `cells` cells whose longest stack holds
    /// `max_size` intervals takes (what bytes() will say once built).
    static uint64_t bytes_for(uint64_t cells, uint32_t max_size)
    {
        const uint64_t groups = (cells + GROUP - 1) / GROUP;
        return groups * GROUP * count_width(max_size) + groups * sizeof(uint64_t);
    }
    /// Bytes per count where the longest stack holds `max_size` intervals.
    static unsigned count_width(uint32_t max_size)
    {
        return max_size <= UINT8_MAX ? 1 : max_size <= UINT16_MAX ? 2 : 4;
    }
    /// Counts, count_bytes() each (host order), padded with zeros to whole
    /// groups; and the offset of every group.
    const uint8_t *count_data() const { return counts_.data(); }
    uint64_t count_data_bytes() const { return counts_.size(); }
    const std::vector<uint64_t> &group_offsets() const { return bases_; }

    uint32_t size(uint64_t cell) const
    {
        const uint8_t *p = counts_.data() + cell * count_bytes_;
        if (count_bytes_ == 1)
            return *p;
        if (count_bytes_ == 2) {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }

    StackRange range(uint64_t cell) const
    {
        const uint64_t group = cell / GROUP;
        const unsigned before = unsigned(cell % GROUP);
        const uint64_t begin = bases_[group] + counts_before(group, before);
        return {begin, begin + size(cell)};
    }

private:
    /// The first k (<= 8) bytes of a little-endian word.
    static uint64_t low_bytes(uint64_t w, unsigned k)
    {
        return k ? w & (~uint64_t(0) >> (64 - 8 * k)) : 0;
    }
    /// Sum of the first `n` (< 16) counts of a group.
    uint64_t counts_before(uint64_t group, unsigned n) const
    {
        const uint8_t *p = counts_.data() + group * GROUP * count_bytes_;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
        if (count_bytes_ == 1) {
            // the 16 counts as two words, those at and after the cell
            // masked off, then summed in 16-bit lanes (at most 15 * 255)
            uint64_t w0, w1;
            std::memcpy(&w0, p, 8);
            std::memcpy(&w1, p + 8, 8);
            w0 = low_bytes(w0, n < 8 ? n : 8);
            w1 = low_bytes(w1, n > 8 ? n - 8 : 0);
            constexpr uint64_t EVEN = 0x00ff00ff00ff00ffULL;
            const uint64_t lanes = (w0 & EVEN) + ((w0 >> 8) & EVEN) + (w1 & EVEN) + ((w1 >> 8) & EVEN);
            return (lanes * 0x0001000100010001ULL) >> 48;
        }
#endif
        uint64_t sum = 0;
        for (unsigned k = 0; k < n; ++k)
            sum += size(group * GROUP + k);
        return sum;
    }

    void allocate(uint64_t cells, uint32_t max_size);
    void set_size(uint64_t cell, uint32_t size);
    void finish_offsets();

    std::vector<uint8_t, UnfilledAllocator<uint8_t>> counts_;
    std::vector<uint64_t> bases_; ///< per group
    uint64_t cells_ = 0, total_ = 0;
    uint32_t max_size_ = 0;
    unsigned count_bytes_ = 1;
};

template <typename Size>
StackIndex StackIndex::from_sizes(const Size *sizes, uint64_t cells)
{
    uint64_t longest = 0;
    for (uint64_t c = 0; c < cells; ++c)
        longest = sizes[c] > longest ? uint64_t(sizes[c]) : longest;
    StackIndex index;
    index.allocate(cells, uint32_t(longest));
    for (uint64_t c = 0; c < cells; ++c)
        index.set_size(c, uint32_t(sizes[c]));
    index.finish_offsets();
    return index;
}

template <typename Offset>
StackIndex StackIndex::from_offsets(const Offset *offsets, uint64_t cells)
{
    if (offsets[0] != 0)
        fail("stack offsets start at ", offsets[0], ", not 0");
    std::vector<uint32_t> sizes(cells);
    for (uint64_t c = 0; c < cells; ++c) {
        if (offsets[c + 1] < offsets[c])
            fail("stack offsets: cell ", c, " has a negative stack size");
        sizes[c] = uint32_t(offsets[c + 1] - offsets[c]);
    }
    return from_sizes(sizes.data(), cells);
}

} // namespace sbrt

#endif
