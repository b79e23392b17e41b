/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Hiding materials
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/hidden_materials.hpp"

#include "util/error.hpp"

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
    std::vector<uint32_t> sizes(cells, 0);
    // the intervals of the kind the model holds
    IntervalArray kept = model.intervals().visit([&](const auto *records) {
        using Record = RecordOf<decltype(records)>;
        std::vector<Record, UnfilledAllocator<Record>> intervals;
        intervals.reserve(model.intervals().size());
        for (uint64_t c = 0; c < cells; ++c) {
            const size_t stack_start = intervals.size();
            const StackRange stack = model.stack(c);
            for (uint64_t i = stack.begin; i < stack.end; ++i) {
                Record iv = records[i];
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
            sizes[c] = uint32_t(intervals.size() - stack_start);
        }
        return IntervalArray(std::move(intervals));
    });
    return Model(model.frame(), model.materials(), StackIndex::from_sizes(sizes.data(), cells),
                 std::move(kept));
}

} // namespace sbrt
