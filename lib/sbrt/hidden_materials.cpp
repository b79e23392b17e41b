/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Hiding materials
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "hidden_materials.hpp"

#include "error.hpp"

namespace sbrt {

Model hide_materials(const Model &model, const std::vector<uint32_t> &hidden)
{
    std::vector<bool> is_hidden(model.materials().size(), false);
    for (uint32_t m : hidden) {
        if (m == EMPTY || m >= is_hidden.size())
            fail("hide_materials: no material with index ", m);
        is_hidden[m] = true;
    }
    const uint64_t cells = model.frame().cells();
    std::vector<uint32_t> offsets(cells + 1, 0);
    Intervals intervals;
    intervals.reserve(model.intervals().size());
    for (uint64_t c = 0; c < cells; ++c) {
        const size_t stack_start = intervals.size();
        for (uint32_t i = model.stack_begin(c); i < model.stack_end(c); ++i) {
            Interval iv = model.intervals()[i];
            if (is_hidden[iv.material])
                iv.material = EMPTY;
            if (intervals.size() > stack_start &&
                intervals.back().material == iv.material)
                intervals.back().top = iv.top; // extend the run
            else
                intervals.push_back(iv);
        }
        if (intervals.size() > stack_start && intervals.back().material == EMPTY)
            intervals.pop_back(); // nothing visible above
        offsets[c + 1] = uint32_t(intervals.size());
    }
    return Model(model.frame(), model.materials(), std::move(offsets),
                 std::move(intervals));
}

} // namespace sbrt
