/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A model read block by block, as a format 2 file with its
 *            column members holds it, beside the model decoded whole: what
 *            the paged tracing and paged GPU tests share, and their check
 *            of hits bit for bit
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TEST_PAGED_CASE_HPP
#define SBRT_TEST_PAGED_CASE_HPP

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "format/format.hpp"
#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/paged_stacks.hpp"
#include "model/column_ranges.hpp"
#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "test_support.hpp"

namespace sbrt_test {

using namespace sbrt;

/// A model (by default of 37 x 45 cells from random voxels) in blocks of
/// 8 (5 x 6 blocks), and its file.
struct PagedCase {
    Model model;
    std::shared_ptr<const std::vector<uint8_t>> bytes;
    std::vector<uint8_t> ranges_member, tops_member; ///< as write_sbrt writes them

    PagedCase() : PagedCase(build_model(random_voxels(29, 37, 45, 26, 6))) {}
    explicit PagedCase(Model m) : model(std::move(m))
    {
        StacksV2Options options;
        options.block_size = 8;
        bytes = std::make_shared<const std::vector<uint8_t>>(encode_stacks_v2(model, options));
        const StacksStamp stamp = stacks_stamp(bytes->data(), bytes->size(), "stacks");
        ranges_member = encode_column_ranges(column_ranges(model), model.frame(), stamp);
        ColumnTopsEncoder tops(model.frame());
        tops.add(column_tops(model));
        tops_member = tops.finish(stamp);
    }
    /// The paged model whose blocks may take `budget` bytes (the budget
    /// given holds the column ranges and pyramid too); with `members`,
    /// opened with its `ranges` and `tops` members, and room for the tops.
    Model paged(uint64_t budget, bool members = false) const
    {
        Paging paging;
        const std::optional<ModelSummary> summary =
            read_stacks_summary(bytes->data(), bytes->size(), "test stacks");
        if (!summary)
            throw Error("no block summaries");
        paging.budget_bytes = room_for_blocks(budget) +
                              skipping_bytes(model.frame(), column_range_bytes(*summary));
        paging.threads = 2;
        StoredRanges stored;
        if (members) {
            paging.budget_bytes += 2 * column_tops_bytes(tops_member.data(), tops_member.size(),
                                                       model.frame(), "tops");
            stored = {{&ranges_member, "ranges"}, {&tops_member, "tops"}};
        }
        std::optional<Model> m = open_paged_model(bytes->data(), bytes->size(), "test stacks",
                                                  bytes, paging, stored);
        if (!m)
            throw Error("not paged");
        return std::move(*m);
    }
    /// Bytes of the largest block decoded.
    uint64_t largest_block() const
    {
        const Model m = paged(uint64_t(1) << 40);
        uint64_t most = 0;
        for (int b = 0; b < m.pages()->block_count(); ++b)
            most = std::max(most, m.pages()->block(b)->bytes());
        return most;
    }
};

/// Every hit of `got` bit for bit `want`'s (the first that is not a fatal
/// failure naming it); `hits` counts the rays that hit.
inline void expect_same_hits(const HitImage &want, const HitImage &got, size_t &hits)
{
    ASSERT_EQ(want.size(), got.size());
    for (size_t i = 0; i < want.size(); ++i) {
        ASSERT_TRUE(identical_hits(want[i], got[i]))
            << i << ": material " << want[i].material << " / " << got[i].material << ", t "
            << want[i].t << " / " << got[i].t << " (" << want[i].t - got[i].t << ")";
        hits += want[i].is_hit();
    }
}

} // namespace sbrt_test

#endif
