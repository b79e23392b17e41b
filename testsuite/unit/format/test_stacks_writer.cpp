/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   An SBRT written band by band of rows (issue 49, item 2: an
 *            import holds a band, not the model) is the SBRT written
 *            whole, byte for byte: the stacks with fields widened by a
 *            later band, each column's range, the coarse level
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "builders/column_builder.hpp"
#include "format/atomic_dir.hpp"
#include "format/format.hpp"
#include "format/sbrt_writer.hpp"
#include "format/stacks_writer.hpp"
#include "scene/level_of_detail.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

/// Feeds every column of `v` (row by row) to `builder`; after each row,
/// `row_done(rows added)`.
template <typename RowDone>
void add_columns(const sbrt_test::Voxels &v, ColumnStackBuilder &builder, RowDone row_done)
{
    const Frame &f = v.frame;
    std::vector<int32_t> column(size_t(f.depths));
    for (int r = 0; r < f.rows; ++r) {
        for (int c = 0; c < f.cols; ++c) {
            for (int z = 0; z < f.depths; ++z)
                column[size_t(z)] = v.classes[(size_t(z) * size_t(f.rows) + size_t(r)) *
                                                  size_t(f.cols) +
                                              size_t(c)];
            builder.add_column(column.data());
        }
        row_done(r + 1);
    }
}

/// `v` built whole, column by column (the material order of a band import).
Model whole_model(const sbrt_test::Voxels &v)
{
    ColumnStackBuilder builder(v.frame);
    add_columns(v, builder, [](int) {});
    return builder.finish();
}

/// `v` built column by column and taken in bands of `band` rows, as an
/// import reading `read` rows at a time takes them: every band but the
/// last whole; each band passed to `take(band model, first row)`.
template <typename Take>
std::vector<Material> in_bands(const sbrt_test::Voxels &v, int band, int read, Take take)
{
    ColumnStackBuilder builder(v.frame);
    int taken = 0;
    add_columns(v, builder, [&](int rows) {
        if (rows % read != 0 && rows != v.frame.rows)
            return;
        while (builder.rows_ready() >= band) {
            take(builder.take_rows(band), taken);
            taken += band;
        }
        if (rows == v.frame.rows && builder.rows_ready() > 0) {
            const int rest = builder.rows_ready();
            take(builder.take_rows(rest), taken);
            taken += rest;
        }
    });
    return builder.materials();
}

std::vector<uint8_t> stacks_in_bands(const sbrt_test::Voxels &v, const StacksV2Options &options,
                                     int band, int read)
{
    StacksWriter writer(v.frame, options);
    const std::vector<Material> materials =
        in_bands(v, band, read, [&](const Model &rows, int) { writer.add_rows(rows); });
    MemorySink sink;
    writer.finish(sink, materials);
    return std::move(sink.bytes());
}

/// Voxels whose first rows hold two classes in short columns and whose
/// last rows hold 300 classes, one column of them in 300 runs: the counts
/// and the materials of a later band need two bytes.
sbrt_test::Voxels narrow_then_wide()
{
    sbrt_test::Voxels v = sbrt_test::random_voxels(3, 8, 5, 600, 2);
    const Frame &f = v.frame;
    for (int r = 4; r < 8; ++r)
        for (int z = 0; z < f.depths; ++z)
            v.classes[(size_t(z) * size_t(f.rows) + size_t(r)) * size_t(f.cols) + 2] =
                1000 + (z / 2) % 300;
    return v;
}

/// The stacks of a model of `frame` from a list of stacks, row by row.
Model model_of(const Frame &frame, size_t materials,
               const std::vector<std::vector<Interval>> &stacks)
{
    std::vector<uint32_t> offsets{0};
    Intervals intervals;
    for (const std::vector<Interval> &stack : stacks) {
        intervals.insert(intervals.end(), stack.begin(), stack.end());
        offsets.push_back(uint32_t(intervals.size()));
    }
    std::vector<Material> table(materials);
    for (size_t m = 1; m < materials; ++m)
        table[m].id = int32_t(m);
    return Model(frame, table, offsets, IntervalArray(std::move(intervals)));
}

std::vector<uint8_t> file_bytes(const std::string &path)
{
    return read_file_bytes(path);
}

} // namespace

TEST(StacksWriter, BandsWriteTheBytesOfTheWholeModel)
{
    const sbrt_test::Voxels v = sbrt_test::random_voxels(21, 70, 45, 40);
    const Model whole = whole_model(v);
    for (const int block : {16, 64}) {
        StacksV2Options options;
        options.block_size = block;
        options.threads = 2;
        const std::vector<uint8_t> expected = encode_stacks_v2(whole, options);
        // bands of one block row and of three, read 5 rows at a time
        EXPECT_EQ(stacks_in_bands(v, options, block, 5), expected) << block;
        EXPECT_EQ(stacks_in_bands(v, options, 3 * block, 7), expected) << block;
    }
}

TEST(StacksWriter, ALaterBandWidensTheFieldsOfEarlierBlocks)
{
    const sbrt_test::Voxels v = narrow_then_wide();
    const Model whole = whole_model(v);
    ASSERT_GT(whole.index().max_size(), 255u);
    ASSERT_GT(whole.materials().size(), 256u);
    StacksV2Options options;
    options.block_size = 4;
    const std::vector<uint8_t> expected = encode_stacks_v2(whole, options);
    EXPECT_EQ(stacks_in_bands(v, options, 4, 4), expected);

    // voxel-boundary tops widened to f32 by a band with a fractional top
    const Frame f = sbrt_test::unit_frame(4, 3, 10, 10);
    std::vector<std::vector<Interval>> stacks(12);
    for (size_t cell = 0; cell < stacks.size(); ++cell)
        stacks[cell] = {{EMPTY, float(1 + cell % 3)}, {1, 5}, {2, float(6 + cell % 4)}};
    stacks[10][1].top = 5.5f;
    const Model fractional = model_of(f, 3, stacks);
    const std::vector<std::vector<Interval>> first(stacks.begin(), stacks.begin() + 6),
        second(stacks.begin() + 6, stacks.end());
    options.block_size = 2;
    StacksWriter writer(f, options);
    writer.add_rows(model_of(frame_rows(f, 0, 2), 3, first));
    writer.add_rows(model_of(frame_rows(f, 2, 2), 3, second));
    MemorySink sink;
    writer.finish(sink, fractional.materials());
    EXPECT_EQ(sink.bytes(), encode_stacks_v2(fractional, options));
}

TEST(StacksWriter, BandsOutOfShapeOrMissingAreRefused)
{
    const sbrt_test::Voxels v = sbrt_test::random_voxels(4, 40, 10, 12);
    StacksV2Options options;
    options.block_size = 16;
    StacksWriter writer(v.frame, options);
    std::vector<Model> bands;
    in_bands(v, 8, 8, [&](Model rows, int) { bands.push_back(std::move(rows)); });
    // 8 rows: not a block row, and not the last band
    EXPECT_THROW(writer.add_rows(bands[0]), Error);
    MemorySink sink;
    EXPECT_THROW(writer.finish(sink, bands.back().materials()), Error);
    EXPECT_THROW(StacksWriter(v.frame, StacksV2Options{0}), Error);
}

TEST(StacksWriter, TakenRowsAreTheRowsOfTheWholeModel)
{
    const sbrt_test::Voxels v = sbrt_test::random_voxels(8, 23, 9, 30);
    const Model whole = whole_model(v);
    in_bands(v, 5, 3, [&](const Model &band, int first) {
        EXPECT_EQ(band.frame().rows, std::min(5, 23 - first));
        EXPECT_EQ(band.frame().north, frame_rows(whole.frame(), first, band.frame().rows).north);
        for (uint64_t cell = 0; cell < band.frame().cells(); ++cell) {
            const uint64_t at = uint64_t(first) * 9 + cell;
            ASSERT_EQ(band.stack_size(cell), whole.stack_size(at)) << at;
            for (uint64_t i = 0; i < band.stack_size(cell); ++i) {
                const Interval a = band.intervals()[band.stack(cell).begin + i];
                const Interval b = whole.intervals()[whole.stack(at).begin + i];
                EXPECT_EQ(a.material, b.material);
                EXPECT_EQ(a.top, b.top);
            }
        }
    });
    ColumnStackBuilder builder(v.frame);
    EXPECT_THROW(builder.take_rows(1), Error);
    // every row taken: finish has none left to give
    add_columns(v, builder, [](int) {});
    builder.take_rows(builder.rows_ready());
    EXPECT_THROW(builder.finish(), Error);
}

TEST(StacksWriter, ASbrtWrittenInBandsIsTheSbrtWrittenWhole)
{
    const sbrt_test::Voxels v = sbrt_test::random_voxels(13, 75, 33, 25);
    Model whole = whole_model(v);
    whole.set_vertical_datum("NAP");
    const std::string dir = sbrt_test::temp_dir("bands");
    StacksV2Options options;
    options.block_size = 16;
    const Model coarse = coarsened(whole, 4);
    write_sbrt(dir + "/whole", whole, "h\n", options, {}, &coarse);

    SbrtWriter writer(dir + "/bands", v.frame, options);
    CoarseLevelBuilder coarse_bands(v.frame, 4);
    const std::vector<Material> materials = in_bands(v, 32, 6, [&](const Model &band, int first) {
        writer.add_rows(band);
        coarse_bands.add_rows(band, first);
    });
    EXPECT_EQ(writer.rows_done(), 75);
    EXPECT_EQ(writer.intervals(), whole.intervals().size());
    EXPECT_EQ(writer.solid_intervals(), whole.stats().solid_intervals);
    const Model coarse_of_bands = coarse_bands.finish(materials);
    writer.finish({materials, "NAP"}, "h\n", {}, &coarse_of_bands);
    for (const char *member : {"stacks", "ranges", "stacks_lod", "header", "cats", "colors",
                               "datum", "hist"})
        EXPECT_EQ(file_bytes(dir + "/bands/" + member), file_bytes(dir + "/whole/" + member))
            << member;
    remove_tree(dir);
}
