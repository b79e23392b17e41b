/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A paged model (blocks decoded as rays reach them, within a
 *            memory budget) traced hit for hit as the model decoded whole;
 *            the budget held; damaged blocks and budgets too small for a
 *            block refused
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <gtest/gtest.h>

#include "format/format.hpp"
#include "model/column_ranges.hpp"
#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/paged_stacks.hpp"
#include "frame/coordinate_frame.hpp"
#include "measure/column_log.hpp"
#include "scene/view.hpp"
#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "test_support.hpp"
#include "paged_case.hpp"

using namespace sbrt;
using sbrt_test::PagedCase;
using sbrt_test::expect_same_hits;

namespace {

/// A paged model's pyramid against the whole model's: level 0 is each
/// column's range of all its material (the column ranges, shared), which
/// holds the whole's cell; the levels above are the same, node for node
/// (hidden strata and cut cells narrow them alike).
void expect_pyramid_over_ranges(const MinMaxPyramid &whole, const MinMaxPyramid &paged,
                                const Model &model)
{
    ASSERT_EQ(whole.levels(), paged.levels());
    ASSERT_TRUE(paged.shares_column_ranges());
    const std::vector<ZRange> ranges = column_ranges(model);
    const auto same = [](const ZRange &a, const ZRange &b) {
        return a.empty() ? b.empty() : a.low == b.low && a.high == b.high;
    };
    for (int y = 0; y < paged.rows(0); ++y)
        for (int x = 0; x < paged.cols(0); ++x) {
            const ZRange &cell = paged.node(0, x, y), &drawn = whole.node(0, x, y);
            ASSERT_TRUE(same(cell, ranges[size_t(paged.rows(0) - 1 - y) * paged.cols(0) + x]));
            ASSERT_TRUE(drawn.empty() || (cell.low <= drawn.low && drawn.high <= cell.high));
        }
    for (int level = 1; level < paged.levels(); ++level)
        for (int y = 0; y < paged.rows(level); ++y)
            for (int x = 0; x < paged.cols(level); ++x)
                ASSERT_TRUE(same(whole.node(level, x, y), paged.node(level, x, y)))
                    << level << " " << x << " " << y;
}

} // namespace

/// Traces the case's model decoded whole and paged (`members`: with its
/// column ranges and top intervals) alike, hit for hit.
void expect_paged_hits_of_the_whole(const PagedCase &c, bool members)
{
    const Frame &f = c.model.frame();
    // room for three blocks: rays keep dropping and decoding blocks again
    const uint64_t budget = 3 * c.largest_block();
    const Model paged = c.paged(budget, members);
    EXPECT_EQ(paged.pages()->has_column_tops(), members);
    EXPECT_EQ(paged.pages()->block_count(), 30);
    EXPECT_EQ(highest_top_local(paged), highest_top_local(c.model));
    EXPECT_EQ(paged.stats().intervals, c.model.stats().intervals);
    EXPECT_EQ(paged.stats().solid_intervals, c.model.stats().solid_intervals);
    const CoordinateFrame frame(f, 3.0, highest_top_local(c.model));
    EXPECT_EQ(framing_hull(paged, frame), framing_hull(c.model, frame));
    for (uint64_t cell = 0; cell < f.cells(); cell += 17) {
        const std::vector<Interval> a = c.model.stack_intervals(cell), b = paged.stack_intervals(cell);
        ASSERT_EQ(a.size(), b.size()) << cell;
        for (size_t i = 0; i < a.size(); ++i)
            ASSERT_TRUE(a[i].material == b[i].material && a[i].top == b[i].top) << cell;
    }

    const glm::dvec3 centre((f.west + f.east) / 2, (f.south + f.north) / 2,
                            f.bottom + f.depths * f.tb_res());
    const std::vector<Camera> cameras = {
        sbrt_test::top_camera(f, 1e4),
        Camera::perspective(centre + glm::dvec3(-70, -95, 90), centre, 40, 60, 80),
        Camera::perspective(centre + glm::dvec3(45, 30, -90), centre, 50, 50, 64),
        Camera::orthographic(centre + glm::dvec3(90, -10, 25), centre, 80, 40, 56)};
    std::vector<uint8_t> hidden(c.model.materials().size(), 0);
    hidden[2] = hidden[4] = 1;
    size_t hits = 0;
    for (int kind = 0; kind < 4; ++kind) {
        // plain, strata hidden while tracing, a cut with a translucent
        // stratum, skipping off
        Scene scene = kind == 2 ? sbrt_test::cut_and_translucent_scene(c.model) : Scene{};
        if (kind == 1)
            scene.hidden = hidden;
        scene.skip_empty_space = kind != 3;
        const Tracer whole(c.model, 3.0, scene), by_pages(paged, 3.0, scene);
        // level 0 is the column ranges themselves, never a narrowed copy;
        // what is hidden or cut narrows the levels above
        EXPECT_EQ(by_pages.pyramid().level_0_wider(), kind == 1 || kind == 2) << kind;
        if (kind != 3)
            expect_pyramid_over_ranges(whole.pyramid(), by_pages.pyramid(), c.model);
        else
            EXPECT_EQ(by_pages.pyramid().levels(), 0);
        for (const Camera &camera : cameras)
            expect_same_hits(trace_image(whole, camera, 2), trace_image(by_pages, camera, 2),
                             hits);
    }
    EXPECT_GT(hits, 20000u);
    // the budget held, and blocks were dropped and decoded again
    const PagingFigures figures = paged.pages()->figures();
    EXPECT_LE(figures.peak_bytes,
              budget + (members ? column_tops_bytes(c.tops_member.data(),
                                                          c.tops_member.size(), f, "tops") : 0));
    EXPECT_GT(figures.decodes, 2u * 30u);
}

TEST(PagedTracing, HitsAreThoseOfTheModelDecodedWhole)
{
    expect_paged_hits_of_the_whole(PagedCase(), false);
}

TEST(PagedTracing, HitsThroughTheColumnsTopIntervalsAreThoseOfTheWhole)
{
    // the top intervals answer the rays that meet only them; those that
    // go below (stepping down a column's side, through hidden and
    // translucent strata, from beneath) walk the blocks' stacks
    expect_paged_hits_of_the_whole(PagedCase(), true);
}

TEST(PagedTracing, ViewFromAboveReadsNoBlockThroughTheTopIntervals)
{
    const PagedCase c;
    const Camera above = sbrt_test::top_camera(c.model.frame(), 1e4);
    const Tracer whole(c.model, 3.0, Scene{});
    const HitImage want = trace_image(whole, above, 2);
    size_t hits = 0;
    for (const bool members : {false, true}) {
        const Model paged = c.paged(uint64_t(1) << 30, members);
        const Tracer by_pages(paged, 3.0, Scene{});
        expect_same_hits(want, trace_image(by_pages, above, 2), hits);
        // every ray stops in a top interval: no block is read with them
        EXPECT_EQ(paged.pages()->figures().decodes == 0, members) << members;
    }
    EXPECT_GT(hits, 1000u);
}

TEST(PagedTracing, HidingPreparesOnlyTheBlocksHoldingTheStratum)
{
    // class 9 only in a few columns of one block (rows 10-12, cols 18-20:
    // block row 1, block col 2 of blocks of 8): hiding it decodes that
    // block alone, and the pyramid is the whole model's
    sbrt_test::Voxels voxels = sbrt_test::random_voxels(31, 29, 37, 26, 6);
    for (int z = 20; z < 26; ++z)
        for (int row = 10; row <= 12; ++row)
            for (int col = 18; col <= 20; ++col)
                voxels.classes[size_t(z) * voxels.frame.cells() +
                               size_t(row) * voxels.frame.cols + size_t(col)] = 9;
    const Model model = sbrt_test::build_model(voxels);
    StacksV2Options options;
    options.block_size = 8;
    const auto bytes = std::make_shared<const std::vector<uint8_t>>(encode_stacks_v2(model, options));
    Paging paging;
    paging.budget_bytes = uint64_t(1) << 30;
    std::vector<ZRange> ranges = column_ranges(model);
    const std::vector<uint8_t> member = encode_column_ranges(
        ranges, model.frame(), stacks_stamp(bytes->data(), bytes->size(), "stacks"));
    StoredRanges stored{{&member, "ranges"}, {}};
    const std::optional<Model> paged =
        open_paged_model(bytes->data(), bytes->size(), "stacks", bytes, paging, stored);
    ASSERT_TRUE(paged);
    ASSERT_EQ(paged->pages()->figures().decodes, 0u);
    const int64_t nine = model.find_material(9);
    ASSERT_GT(nine, 0);
    Scene scene;
    scene.hidden.assign(model.materials().size(), 0);
    scene.hidden[size_t(nine)] = 1;
    const Tracer whole(model, 3.0, scene), by_pages(*paged, 3.0, scene);
    EXPECT_EQ(paged->pages()->figures().decodes, 1u);
    expect_pyramid_over_ranges(whole.pyramid(), by_pages.pyramid(), model);
}

TEST(PagedTracing, BudgetBelowOneBlockIsRefused)
{
    const PagedCase c;
    try {
        c.paged(c.largest_block() - 1);
        FAIL() << "a budget below one block was taken";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("give memory= at least"), std::string::npos)
            << e.what();
    }
    EXPECT_NO_THROW(c.paged(c.largest_block()));
    // the summaries tell the largest block before any is decoded
    const auto summary = read_stacks_summary(c.bytes->data(), c.bytes->size(), "x");
    ASSERT_TRUE(summary);
    EXPECT_EQ(summary->largest_decoded_block(), c.largest_block());
}

TEST(PagedTracing, ColumnsAreReadWithoutTheirRanges)
{
    // a reader of single columns (a virtual borehole, a profile) opens
    // the model without the column ranges: nothing is decoded on opening,
    // and each stack read is the whole model's
    const PagedCase c;
    Paging paging;
    paging.budget_bytes = 2 * c.largest_block(); // no room for ranges: none needed
    paging.column_ranges = Paging::Ranges::none;
    const std::optional<Model> paged =
        open_paged_model(c.bytes->data(), c.bytes->size(), "test stacks", c.bytes, paging);
    ASSERT_TRUE(paged);
    EXPECT_FALSE(paged->pages()->has_column_ranges());
    EXPECT_EQ(paged->pages()->figures().decodes, 0u);
    EXPECT_THROW(paged->pages()->column_ranges(), Error);
    for (uint64_t cell = 0; cell < c.model.frame().cells(); ++cell) {
        const std::vector<Interval> want = c.model.stack_intervals(cell);
        const std::vector<Interval> got = paged->stack_intervals(cell);
        ASSERT_EQ(got.size(), want.size()) << cell;
        for (size_t i = 0; i < want.size(); ++i) {
            EXPECT_EQ(got[i].material, want[i].material) << cell;
            EXPECT_EQ(got[i].top, want[i].top) << cell;
        }
        EXPECT_EQ(paged->stack_top(cell), c.model.stack_top(cell)) << cell;
        const GridCell at{int(cell / uint64_t(c.model.frame().cols)),
                          int(cell % uint64_t(c.model.frame().cols))};
        const ColumnLog paged_log = column_log(*paged, at), whole_log = column_log(c.model, at);
        ASSERT_EQ(paged_log.entries.size(), whole_log.entries.size()) << cell;
        for (size_t i = 0; i < whole_log.entries.size(); ++i) {
            EXPECT_EQ(paged_log.entries[i].material, whole_log.entries[i].material) << cell;
            EXPECT_EQ(paged_log.entries[i].top, whole_log.entries[i].top) << cell;
            EXPECT_EQ(paged_log.entries[i].bottom, whole_log.entries[i].bottom) << cell;
        }
    }
    EXPECT_LE(paged->pages()->figures().peak_bytes, 2 * c.largest_block());
}

TEST(PagedTracing, ReservedBytesAreNotForBlocks)
{
    const PagedCase c;
    const auto summary = read_stacks_summary(c.bytes->data(), c.bytes->size(), "x");
    ASSERT_TRUE(summary);
    // a voxel model's column ranges are u16 pairs: 4 bytes a column
    ASSERT_EQ(column_range_bytes(*summary), 4u);
    const uint64_t skipping = skipping_bytes(summary->frame, 4);
    EXPECT_EQ(skipping_bytes(summary->frame), skipping + summary->frame.cells() * 4);
    const uint64_t block = c.largest_block();
    Paging paging;
    paging.reserved_bytes = uint64_t(5) << 20; // the process and its images
    paging.budget_bytes = skipping + paging.reserved_bytes + room_for_blocks(block);
    EXPECT_GE(block_budget(*summary, paging), block);
    EXPECT_LT(block_budget(*summary, paging), block + block / 7 + 8); // the heap's share
    paging.budget_bytes -= 1;
    try {
        block_budget(*summary, paging);
        FAIL() << "a budget that leaves less than a block beside the reserved bytes was taken";
    }
    catch (const Error &e) {
        const std::string why = e.what();
        EXPECT_NE(why.find("the rest of this process (its code, buffers and a block for each thread), 6 MB"), std::string::npos) << why;
        const uint64_t least =
            ((skipping + paging.reserved_bytes + room_for_blocks(block)) >> 20) + 1;
        EXPECT_NE(why.find("give memory= at least " + std::to_string(least)), std::string::npos)
            << why;
    }
}

TEST(PagedTracing, DamagedBlockIsRefusedOnOpening)
{
    const PagedCase c;
    const StacksV2Layout layout = open_stacks_v2(c.bytes->data(), c.bytes->size(), "x");
    auto damaged = std::make_shared<std::vector<uint8_t>>(*c.bytes);
    (*damaged)[layout.entries[17].offset + 5] ^= 0x40;
    Paging paging;
    paging.budget_bytes = uint64_t(1) << 30;
    try {
        open_paged_model(damaged->data(), damaged->size(), "test stacks", damaged, paging);
        FAIL() << "a damaged block was taken";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("block 17"), std::string::npos) << e.what();
    }
}

TEST(PagedTracing, OlderFilesAndBoreholesAreNotPaged)
{
    const PagedCase c;
    StacksV2Options options;
    options.summary = false; // 2.0: no block summaries
    const auto older = std::make_shared<const std::vector<uint8_t>>(encode_stacks_v2(c.model, options));
    Paging paging;
    paging.budget_bytes = uint64_t(1) << 30;
    EXPECT_FALSE(open_paged_model(older->data(), older->size(), "x", older, paging));
    const Model paged = c.paged(uint64_t(1) << 30);
    Scene scene;
    scene.boreholes = {sbrt_test::borehole_at(c.model, 600, 1200)};
    scene.borehole_radius = 1;
    EXPECT_THROW(Tracer(paged, 1.0, scene), Error);
}

TEST(PagedTracing, UnsoundStacksAreRefusedAsWhenDecodedWhole)
{
    // blocks whose checksums hold but whose stacks break an invariant:
    // refused on opening, as decoding the model whole refuses them
    Frame f;
    f.rows = 3;
    f.cols = 4;
    f.depths = 10;
    const std::vector<Material> materials(3);
    const std::vector<std::vector<Interval>> unsound = {
        {{1, 4}, {1, 7}},   // two adjacent intervals of one material
        {{1, 4}, {0, 7}},   // a trailing EMPTY
        {{2, 4}, {1, 4}},   // tops not rising
        {{5, 4}},           // a material index out of range
    };
    for (const std::vector<Interval> &stack : unsound) {
        std::vector<uint32_t> offsets(f.cells() + 1, 0);
        Intervals intervals;
        for (uint64_t c = 0; c < f.cells(); ++c) {
            const std::vector<Interval> cell =
                c == 6 ? stack : std::vector<Interval>{{1, 3}, {2, 9}};
            intervals.insert(intervals.end(), cell.begin(), cell.end());
            offsets[c + 1] = uint32_t(intervals.size());
        }
        std::vector<Material> m = materials;
        m.resize(stack[0].material == 5 ? 6 : 3); // the writer's widths take it
        const Model model(f, m, offsets, IntervalArray(std::move(intervals)));
        StacksV2Options options;
        options.block_size = 2;
        auto bytes = std::make_shared<std::vector<uint8_t>>(encode_stacks_v2(model, options));
        if (stack[0].material == 5) { // the header says 3 materials
            m.resize(3);
            const Model fewer(f, m, offsets, model.intervals());
            // (encoded with 3 materials, the block holds index 5)
            bytes = std::make_shared<std::vector<uint8_t>>(encode_stacks_v2(fewer, options));
        }
        EXPECT_THROW(decode_stacks_v2(bytes->data(), bytes->size(), "x"), Error);
        Paging paging;
        paging.budget_bytes = 1 << 20;
        try {
            open_paged_model(bytes->data(), bytes->size(), "paged", bytes, paging);
            ADD_FAILURE() << "unsound stack taken: " << stack.size();
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("paged block"), std::string::npos) << e.what();
        }
    }
}

TEST(PagedTracing, TopIntervalsAreHeldWhereTheBudgetHasRoomForThem)
{
    // up to three quarters of what the budget leaves beside its least
    const PagedCase c;
    const auto summary = read_stacks_summary(c.bytes->data(), c.bytes->size(), "x");
    ASSERT_TRUE(summary);
    Paging paging;
    paging.budget_bytes = least_budget(*summary, paging) + 4000;
    EXPECT_TRUE(tops_fit(*summary, paging, 3000));
    EXPECT_FALSE(tops_fit(*summary, paging, 3001));
    EXPECT_FALSE(tops_fit(*summary, paging, 0)); // none stored
    // opened where they do not fit: the blocks answer every ray alike
    const uint64_t tops = column_tops_bytes(c.tops_member.data(), c.tops_member.size(),
                                            c.model.frame(), "tops");
    paging.budget_bytes = least_budget(*summary, paging) + tops;
    const StoredRanges stored{{&c.ranges_member, "ranges"}, {&c.tops_member, "tops"}};
    const std::optional<Model> paged =
        open_paged_model(c.bytes->data(), c.bytes->size(), "x", c.bytes, paging, stored);
    ASSERT_TRUE(paged);
    EXPECT_FALSE(paged->pages()->has_column_tops());
    const Camera above = sbrt_test::top_camera(c.model.frame(), 1e4);
    size_t hits = 0;
    expect_same_hits(trace_image(Tracer(c.model, 3.0, Scene{}), above, 2),
                     trace_image(Tracer(*paged, 3.0, Scene{}), above, 2), hits);
    EXPECT_GT(paged->pages()->figures().decodes, 0u);
}

TEST(PagedTracing, ASmallerBudgetDropsBlocksAtOnceAndStillTraces)
{
    // a view server gives part of the blocks' budget to the coarse level
    const PagedCase c;
    const Model paged = c.paged(uint64_t(1) << 30);
    const Camera camera = sbrt_test::top_camera(c.model.frame(), 1e4);
    const Tracer whole(c.model, 3.0, Scene{}), by_pages(paged, 3.0, Scene{});
    const HitImage want = trace_image(whole, camera, 2);
    size_t hits = 0;
    expect_same_hits(want, trace_image(by_pages, camera, 2), hits);
    ASSERT_GT(paged.pages()->figures().held_bytes, 2 * c.largest_block());
    const uint64_t smaller = c.largest_block() / 2; // below one block: the newest stays
    paged.pages()->set_budget_bytes(smaller);
    EXPECT_LE(paged.pages()->figures().held_bytes, smaller);
    expect_same_hits(want, trace_image(by_pages, camera, 2), hits);
    EXPECT_LE(paged.pages()->figures().held_bytes, c.largest_block());
}
