/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The `tops` member: written beside the stacks, read back as
 *            each column's top interval of the decoded model; a stale
 *            member ignored, a damaged one or one its ranges contradict
 *            refused; continuous tops kept wide
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/

#include <gtest/gtest.h>

#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/format.hpp"
#include "model/column_ranges.hpp"
#include "util/error.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

Paging roomy()
{
    Paging paging;
    paging.budget_bytes = uint64_t(1) << 30;
    return paging;
}

/// Whether `got` holds the top intervals `want` (column_tops), record
/// for record.
void expect_tops(const IntervalArray &got, const std::vector<Interval> &want)
{
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        ASSERT_EQ(got[i].material, want[i].material) << i;
        ASSERT_EQ(got[i].top, want[i].top) << i;
    }
}

} // namespace

TEST(ColumnTopsFile, PagedModelHoldsEachColumnsTopInterval)
{
    const Model model = sbrt_test::model_with_air_columns(41); // and columns of air
    const std::vector<Interval> want = column_tops(model);
    size_t empty = 0, single = 0;
    for (const Interval &top : want) {
        empty += top.material == EMPTY;
        single += top.material != EMPTY && top.top == 0;
    }
    ASSERT_GT(empty, 0u);
    const std::string dir = sbrt_test::temp_dir("tops") + "/m";
    write_sbrt(dir, model, "test");
    const std::optional<Model> paged = read_sbrt_paged(dir, roomy());
    ASSERT_TRUE(paged && paged->pages()->has_column_tops());
    EXPECT_TRUE(paged->pages()->column_tops().is_compact()); // voxel boundaries
    expect_tops(paged->pages()->column_tops(), want);
    EXPECT_EQ(paged->pages()->figures().decodes, 0u);
    // each record is the top of the column's stack
    for (uint64_t cell = 0; cell < want.size(); cell += 13) {
        const std::vector<Interval> stack = model.stack_intervals(cell);
        if (stack.empty())
            continue;
        EXPECT_EQ(want[cell].material, stack.back().material) << cell;
        EXPECT_EQ(want[cell].top, stack.size() > 1 ? stack[stack.size() - 2].top : 0.0f) << cell;
    }

    // a member made from other stacks is ignored
    const Model other = sbrt_test::build_model(sbrt_test::random_voxels(42, 70, 90, 24, 5));
    write_sbrt(dir + "_other", other, "test");
    const std::vector<uint8_t> member = read_file_bytes(dir + "/tops");
    sbrt_test::put_file_bytes(dir + "/tops", read_file_bytes(dir + "_other/tops"));
    const std::optional<Model> stale = read_sbrt_paged(dir, roomy());
    ASSERT_TRUE(stale);
    EXPECT_FALSE(stale->pages()->has_column_tops());

    // a damaged member is refused, naming it
    for (const size_t at : {size_t(3), size_t(16), member.size() - 2}) {
        std::vector<uint8_t> damaged = member;
        damaged[at] ^= 0x20;
        sbrt_test::put_file_bytes(dir + "/tops", damaged);
        try {
            read_sbrt_paged(dir, roomy());
            FAIL() << "a damaged tops member was taken (" << at << ")";
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("tops"), std::string::npos) << e.what();
        }
    }
    // without the member (an SBRT written before it), the blocks are read
    std::remove((dir + "/tops").c_str());
    const std::optional<Model> older = read_sbrt_paged(dir, roomy());
    ASSERT_TRUE(older);
    EXPECT_FALSE(older->pages()->has_column_tops());
}

TEST(ColumnTopsFile, RecordsTheirRangesContradictAreRefused)
{
    const Frame f = sbrt_test::unit_frame(1, 3, 10);
    std::vector<ZRange> ranges(f.cells());
    ranges[0] = {0.0f, 4.0f};
    ranges[1] = {2.0f, 9.0f};
    // the ranges held as a paged model holds a voxel model's: compact
    const ColumnRangeArray held(CompactRanges{{0, 4}, {2, 9}, {}});
    ASSERT_TRUE(held.is_compact());
    const StacksStamp stamp{7, 8, 9};
    const auto encoded = [&](const std::vector<Interval> &tops) {
        ColumnTopsEncoder encoder(f);
        encoder.add(tops);
        return encoder.finish(stamp);
    };
    const std::vector<Interval> sound = {{1, 0.0f}, {2, 5.0f}, {EMPTY, 0.0f}};
    const std::vector<uint8_t> bytes = encoded(sound);
    const auto back = decode_column_tops(bytes.data(), bytes.size(), "tops", f, stamp, held, 3);
    ASSERT_TRUE(back);
    expect_tops(*back, sound);
    const std::vector<std::vector<Interval>> contradicted = {
        {{1, 4.0f}, {2, 5.0f}, {EMPTY, 0.0f}},  // a bottom at the column's top
        {{1, 0.0f}, {2, 1.0f}, {EMPTY, 0.0f}},  // a bottom below its range
        {{1, 0.0f}, {2, 0.0f}, {EMPTY, 0.0f}},  // one interval where the range starts higher
        {{1, 0.0f}, {3, 5.0f}, {EMPTY, 0.0f}},  // no such material
        {{1, 0.0f}, {2, 5.0f}, {1, 0.0f}},      // material in an empty column
        {{EMPTY, 0.0f}, {2, 5.0f}, {EMPTY, 0.0f}}}; // none in a column with some
    for (const std::vector<Interval> &tops : contradicted) {
        const std::vector<uint8_t> bad = encoded(tops);
        EXPECT_THROW(decode_column_tops(bad.data(), bad.size(), "tops", f, stamp, held, 3),
                     Error);
    }
    // made from other stacks: nothing
    EXPECT_FALSE(decode_column_tops(bytes.data(), bytes.size(), "tops", f, StacksStamp{7, 8, 10},
                                    held, 3));
}

TEST(ColumnTopsFile, ContinuousBottomsAreKeptWide)
{
    // a bottom off the voxel boundaries (horizons) turns the member wide,
    // the records before it too
    const Frame f = sbrt_test::unit_frame(2, 2, 10);
    const ColumnRangeArray ranges(
        std::vector<ZRange>{{0.0f, 3.0f}, {1.0f, 9.5f}, {0.0f, 8.0f}, {}});
    const std::vector<Interval> tops = {{1, 2.0f}, {2, 7.25f}, {1, 0.0f}, {EMPTY, 0.0f}};
    ColumnTopsEncoder encoder(f);
    encoder.add({tops[0]});
    encoder.add({tops.begin() + 1, tops.end()});
    const StacksStamp stamp{1, 2, 3};
    const std::vector<uint8_t> bytes = encoder.finish(stamp);
    EXPECT_EQ(column_tops_bytes(bytes.data(), bytes.size(), f, "tops"), 4u * 8u);
    const auto back = decode_column_tops(bytes.data(), bytes.size(), "tops", f, stamp, ranges, 3);
    ASSERT_TRUE(back);
    EXPECT_FALSE(back->is_compact());
    expect_tops(*back, tops);
    // a record too many, or one missing, is refused
    EXPECT_THROW(encoder.add({Interval{EMPTY, 0.0f}}), Error);
    ColumnTopsEncoder short_of_one(f);
    short_of_one.add(std::vector<Interval>(3, Interval{EMPTY, 0.0f}));
    EXPECT_THROW(short_of_one.finish(stamp), Error);
}
