/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Hiding materials
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/hidden_materials.hpp"

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// The stack [first, last) with hidden materials made EMPTY, runs merged
/// and a trailing EMPTY run dropped, written from `out` on (nullptr: only
/// counted); returns its size. A run is written once it ends, so nothing
/// lands beyond the stack's own size.
template <typename Record>
uint32_t hidden_stack(const Record *first, const Record *last,
                      const std::vector<char> &is_hidden, Record *out)
{
    uint32_t size = 0;
    Record run{};
    bool open = false;
    for (const Record *r = first; r != last; ++r) {
        Record iv = *r;
        if (is_hidden[iv.material])
            iv.material = EMPTY;
        if (open && run.material == iv.material) {
            run.top = iv.top; // extend the run
            continue;
        }
        if (open) {
            if (out)
                out[size] = run;
            ++size;
        }
        run = iv;
        open = true;
    }
    if (open && run.material != EMPTY) { // an EMPTY run on top: nothing visible above
        if (out)
            out[size] = run;
        ++size;
    }
    return size;
}

} // namespace

Model hide_materials(const Model &model, const std::vector<uint32_t> &hidden)
{
    std::vector<char> is_hidden(model.materials().size(), 0);
    for (uint32_t m : hidden) {
        if (m == EMPTY || m >= is_hidden.size())
            fail("hide_materials: no material with index ", m);
        is_hidden[m] = 1;
    }
    const Frame &f = model.frame();
    const uint64_t cells = f.cells();
    std::vector<uint32_t> sizes(cells, 0);
    // the intervals of the kind the model holds, row by row on all cores:
    // the stacks' sizes first, then each row's into its place
    IntervalArray kept = model.intervals().visit([&](const auto *records) {
        using Record = RecordOf<decltype(records)>;
        for_each_row(f.rows, 0, [&](int row) {
            for (uint64_t c = model.cell_index(row, 0); c < model.cell_index(row + 1, 0); ++c) {
                const StackRange stack = model.stack(c);
                sizes[c] = hidden_stack<Record>(records + stack.begin, records + stack.end,
                                                is_hidden, nullptr);
            }
        });
        const StackIndex index = StackIndex::from_sizes(sizes.data(), cells);
        std::vector<Record, UnfilledAllocator<Record>> intervals(index.total());
        for_each_row(f.rows, 0, [&](int row) {
            for (uint64_t c = model.cell_index(row, 0); c < model.cell_index(row + 1, 0); ++c) {
                const StackRange stack = model.stack(c);
                hidden_stack<Record>(records + stack.begin, records + stack.end, is_hidden,
                                     intervals.data() + index.range(c).begin);
            }
        });
        return IntervalArray(std::move(intervals));
    });
    return Model(f, model.materials(), StackIndex::from_sizes(sizes.data(), cells),
                 std::move(kept));
}

} // namespace sbrt
