/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Stack index: counts and group offsets built
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/stack_index.hpp"

#include <algorithm>

namespace sbrt {

void StackIndex::allocate(uint64_t cells, uint32_t max_size)
{
    cells_ = cells;
    max_size_ = max_size;
    count_bytes_ = count_width(max_size);
    const uint64_t groups = (cells + GROUP - 1) / GROUP;
    counts_.resize(groups * GROUP * count_bytes_);
    // the padding of the last group counts nothing
    std::fill(counts_.begin() + cells * count_bytes_, counts_.end(), uint8_t(0));
    bases_.assign(groups, 0);
}

void StackIndex::set_size(uint64_t cell, uint32_t size)
{
    uint8_t *p = counts_.data() + cell * count_bytes_;
    if (count_bytes_ == 1) {
        *p = uint8_t(size);
    }
    else if (count_bytes_ == 2) {
        const uint16_t v = uint16_t(size);
        std::memcpy(p, &v, 2);
    }
    else {
        std::memcpy(p, &size, 4);
    }
}

void StackIndex::finish_offsets()
{
    uint64_t total = 0;
    for (uint64_t g = 0; g < bases_.size(); ++g) {
        bases_[g] = total;
        for (unsigned k = 0; k < GROUP; ++k)
            total += size(g * GROUP + k);
    }
    total_ = total;
}

} // namespace sbrt
