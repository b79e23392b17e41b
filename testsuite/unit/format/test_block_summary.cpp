/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Format 2.1 block summaries: equal to what the decoded model
 *            holds, Table 1 figures equal to Model::stats(), 2.0 files
 *            without them decoded instead, damaged or truncated sections
 *            refused with an sbrt::Error, never a crash
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/block_summary.hpp"
#include "format/byte_io.hpp"
#include "format/format.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

// offsets in the 2.0 header (format_v2.hpp)
constexpr size_t AT_MINOR = 10, AT_OPTIONAL = 20, AT_TABLE = 124;

uint64_t field(const std::vector<uint8_t> &b, size_t at, int n)
{
    uint64_t v = 0;
    for (int i = 0; i < n; ++i)
        v |= uint64_t(b[at + size_t(i)]) << (8 * i);
    return v;
}

/// A voxel model whose first `empty_rows` rows hold nothing.
Model voxel_model(unsigned seed, int rows, int cols, int depths, int empty_rows)
{
    sbrt_test::Voxels v = sbrt_test::random_voxels(seed, rows, cols, depths);
    for (int z = 0; z < depths; ++z)
        for (int r = 0; r < empty_rows; ++r)
            for (int c = 0; c < cols; ++c)
                v.classes[(size_t(z) * rows + r) * cols + c] = NULL_CLASS;
    return sbrt_test::build_model(v);
}

/// A model of continuous tops (held wide): every stack EMPTY below a
/// non-integer height, then solid runs.
Model float_model(int rows, int cols)
{
    Frame f;
    f.rows = rows;
    f.cols = cols;
    f.depths = 40;
    std::vector<Material> table(6);
    for (int i = 1; i <= 5; ++i)
        table[size_t(i)].id = i * 3;
    std::vector<uint32_t> offsets(f.cells() + 1, 0);
    Intervals intervals;
    for (uint64_t c = 0; c < f.cells(); ++c) {
        if (c % 5 != 3) {
            intervals.push_back({EMPTY, 1.25f + float(c % 7)});
            intervals.push_back({1 + uint32_t(c % 5), 20.5f + float(c % 11)});
            intervals.push_back({1 + uint32_t((c + 1) % 5), 33.75f});
        }
        offsets[c + 1] = uint32_t(intervals.size());
    }
    return Model(f, std::move(table), offsets, IntervalArray(std::move(intervals)));
}

/// The summary of `block` (cells [r0, r0 + size) x [c0, c0 + size)),
/// counted here from the model's intervals, not by BlockSummarizer.
BlockSummary expected_summary(const Model &m, int r0, int c0, int size)
{
    BlockSummary s;
    std::vector<bool> present(m.materials().size(), false);
    const Frame &f = m.frame();
    for (int r = r0; r < std::min(f.rows, r0 + size); ++r)
        for (int c = c0; c < std::min(f.cols, c0 + size); ++c) {
            const std::vector<Interval> stack = m.stack_intervals(m.cell_index(r, c));
            if (stack.empty())
                continue;
            s.intervals += uint32_t(stack.size());
            s.longest_stack = std::max(s.longest_stack, uint32_t(stack.size()));
            ++s.filled_cells;
            s.z_low = std::min(s.z_low, stack[0].material == EMPTY ? stack[0].top : 0.0f);
            s.z_high = std::max(s.z_high, stack.back().top);
            for (const Interval &iv : stack) {
                s.solid_intervals += iv.material != EMPTY;
                present[iv.material] = present[iv.material] || iv.material != EMPTY;
                s.compact = s.compact && fits_compact(iv);
            }
        }
    for (size_t k = 0; k < present.size(); ++k)
        if (present[k])
            s.materials.push_back(uint16_t(k));
    return s;
}

void expect_same_stats(const Stats &a, const Stats &b)
{
    EXPECT_EQ(a.voxels, b.voxels);
    EXPECT_EQ(a.voxel_bytes, b.voxel_bytes);
    EXPECT_EQ(a.sbrt_bytes, b.sbrt_bytes);
    EXPECT_EQ(a.index_bytes, b.index_bytes);
    EXPECT_EQ(a.interval_bytes, b.interval_bytes);
    EXPECT_EQ(a.intervals, b.intervals);
    EXPECT_EQ(a.solid_intervals, b.solid_intervals);
    EXPECT_EQ(a.max_stack, b.max_stack);
    // bit for bit: the report prints them
    EXPECT_EQ(a.mean_stack, b.mean_stack);
    EXPECT_EQ(a.compression_percent, b.compression_percent);
}

/// The summary of `bytes`, checked against the model they decode to.
void expect_summary_of_decoded(const std::vector<uint8_t> &bytes, int block_size)
{
    const std::optional<ModelSummary> s = read_stacks_summary(bytes.data(), bytes.size(), "t");
    ASSERT_TRUE(s);
    const Model m = decode_stacks(bytes.data(), bytes.size(), "t");
    const Frame &f = m.frame();
    EXPECT_EQ(s->block_size, block_size);
    EXPECT_EQ(s->frame.rows, f.rows);
    EXPECT_EQ(s->frame.depths, f.depths);
    ASSERT_EQ(s->materials.size(), m.materials().size());
    for (size_t i = 0; i < s->materials.size(); ++i)
        EXPECT_EQ(s->materials[i].id, m.materials()[i].id);
    const int block_cols = (f.cols + block_size - 1) / block_size;
    ASSERT_EQ(s->blocks.size(),
              size_t((f.rows + block_size - 1) / block_size) * size_t(block_cols));
    for (size_t b = 0; b < s->blocks.size(); ++b) {
        const BlockSummary want = expected_summary(m, int(b) / block_cols * block_size,
                                                   int(b) % block_cols * block_size, block_size);
        EXPECT_TRUE(s->blocks[b] == want) << "block " << b;
    }
    expect_same_stats(s->stats, m.stats());
}

std::string summary_error(const std::vector<uint8_t> &bytes)
{
    try {
        read_stacks_summary(bytes.data(), bytes.size(), "t");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

/// Where the summary section lies: [begin, table offset).
std::pair<size_t, size_t> summary_section(const std::vector<uint8_t> &bytes)
{
    const size_t table = size_t(field(bytes, AT_TABLE, 8));
    const size_t size = size_t(field(bytes, table - 8, 8));
    return {table - size, table};
}

} // namespace

TEST(BlockSummary, SummariesAndStatsEqualThoseOfTheDecodedModel)
{
    for (const auto &[rows, cols, depths] : {std::tuple{1, 1, 1}, {7, 9, 20}, {33, 40, 90}}) {
        const Model model = voxel_model(unsigned(rows * 13 + cols), rows, cols, depths, rows / 3);
        for (int block : {1, 4, 16, 64}) {
            StacksV2Options options;
            options.block_size = block;
            expect_summary_of_decoded(encode_stacks_v2(model, options), block);
        }
    }
    StacksV2Options options;
    options.block_size = 4;
    const Model horizons = float_model(9, 11);
    EXPECT_FALSE(horizons.intervals().is_compact());
    expect_summary_of_decoded(encode_stacks_v2(horizons, options), 4);
}

TEST(BlockSummary, HeightRangesAndClassesOfKnownStacks)
{
    const Model m = float_model(9, 11);
    StacksV2Options options;
    options.block_size = 4;
    const auto bytes = encode_stacks_v2(m, options);
    const ModelSummary s = *read_stacks_summary(bytes.data(), bytes.size(), "t");
    // block 0: cells 0..3 of rows 0..3 (cells c = 11 r + c, c % 5 == 3 empty)
    const BlockSummary &b = s.blocks[0];
    EXPECT_EQ(b.filled_cells, 12u);
    EXPECT_EQ(b.intervals, 36u);
    EXPECT_EQ(b.solid_intervals, 24u);
    EXPECT_EQ(b.longest_stack, 3u);
    EXPECT_EQ(b.z_low, 1.25f);  // above the leading EMPTY of cell 0
    EXPECT_EQ(b.z_high, 33.75f);
    EXPECT_FALSE(b.compact);
    EXPECT_EQ(b.materials, (std::vector<uint16_t>{1, 2, 3, 4, 5}));
    EXPECT_TRUE(b.holds(3));
    EXPECT_FALSE(b.holds(EMPTY));
    // an empty block: the marker, no classes
    const Model top_empty = voxel_model(3, 12, 12, 30, 4);
    const auto v = encode_stacks_v2(top_empty, options);
    const ModelSummary e = *read_stacks_summary(v.data(), v.size(), "t");
    EXPECT_TRUE(e.blocks[0].is_empty());
    EXPECT_TRUE(std::isinf(e.blocks[0].z_low) && e.blocks[0].z_low > 0);
    EXPECT_TRUE(e.blocks[0].materials.empty());
    EXPECT_FALSE(e.blocks[4].is_empty());
}

TEST(BlockSummary, A20FileHasNoSummaryAndDecodesAlike)
{
    const Model model = voxel_model(5, 20, 21, 30, 2);
    StacksV2Options options;
    options.block_size = 8;
    const auto v21 = encode_stacks_v2(model, options);
    options.summary = false;
    const auto v20 = encode_stacks_v2(model, options);
    EXPECT_EQ(field(v21, AT_MINOR, 2), 1u);
    EXPECT_EQ(field(v20, AT_MINOR, 2), 0u);
    EXPECT_TRUE(field(v21, AT_OPTIONAL, 4) & V2_OPTIONAL_SUMMARY);
    EXPECT_FALSE(field(v20, AT_OPTIONAL, 4) & V2_OPTIONAL_SUMMARY);
    // the 2.1 file is the 2.0 file with the section before the table
    const auto [begin, end] = summary_section(v21);
    EXPECT_EQ(v21.size() - v20.size(), end - begin);
    EXPECT_FALSE(read_stacks_summary(v20.data(), v20.size(), "t"));
    EXPECT_EQ(encode_stacks_v1(decode_stacks(v20.data(), v20.size(), "t")),
              encode_stacks_v1(decode_stacks(v21.data(), v21.size(), "t")));
    // v1: no summary either
    const auto v1 = encode_stacks_v1(model);
    EXPECT_FALSE(read_stacks_summary(v1.data(), v1.size(), "t"));
}

TEST(BlockSummary, DirectoriesAreDescribedWithTheirLegendOrNotAtAll)
{
    Model model = voxel_model(8, 10, 12, 25, 1);
    model.materials()[1].label = "klei";
    model.materials()[2].has_color = true;
    model.materials()[2].red = 200;
    model.set_vertical_datum("NAP");
    const std::string parent = sbrt_test::temp_dir("summary");
    const std::string dir = parent + "/m";
    write_sbrt(dir, model, "h\n");
    const std::optional<ModelSummary> s = read_sbrt_summary(dir);
    ASSERT_TRUE(s);
    const Model read = read_sbrt(dir);
    EXPECT_EQ(s->materials[1].label, "klei");
    EXPECT_TRUE(s->materials[2].has_color);
    EXPECT_EQ(s->materials[2].red, 200);
    EXPECT_EQ(s->vertical_datum, "NAP");
    EXPECT_FALSE(s->has_channels);
    expect_same_stats(s->stats, read.stats());
    // a version 1 directory is read whole instead
    {
        AtomicDirectory out(dir);
        out.write_file("stacks", encode_stacks_v1(model));
        out.commit();
    }
    EXPECT_FALSE(read_sbrt_summary(dir));
    remove_tree(parent);
}

TEST(BlockSummary, EveryFlippedByteOfTheSectionIsAnError)
{
    const Model model = voxel_model(9, 12, 13, 30, 3);
    StacksV2Options options;
    options.block_size = 5;
    const auto bytes = encode_stacks_v2(model, options);
    const auto [begin, end] = summary_section(bytes);
    ASSERT_GT(end - begin, 16u);
    for (size_t at = begin; at < end; ++at)
        for (const uint8_t bit : {uint8_t(1), uint8_t(0x80)}) {
            std::vector<uint8_t> bad = bytes;
            bad[at] ^= bit;
            const std::string message = summary_error(bad);
            ASSERT_NE(message.find("t block summaries: "), std::string::npos)
                << "byte " << at - begin << ": " << message;
            // decoding checks the section's size and checksum too: no
            // byte of a file goes unchecked
            EXPECT_THROW(decode_stacks(bad.data(), bad.size(), "t"), Error);
        }
}

TEST(BlockSummary, RecordsWithValidChecksumsButWrongFieldsAreErrors)
{
    const Model model = voxel_model(10, 12, 13, 30, 3);
    StacksV2Options options;
    options.block_size = 5;
    const auto bytes = encode_stacks_v2(model, options);
    const auto [begin, end] = summary_section(bytes);
    const size_t records = end - 16;
    std::mt19937 rng(17);
    int refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::vector<uint8_t> bad = bytes;
        bad[begin + rng() % (records - begin)] ^= uint8_t(1u << (rng() % 8));
        const uint32_t crc = crc32_of(bad.data() + begin, records - begin);
        for (int i = 0; i < 4; ++i)
            bad[end - 12 + size_t(i)] = uint8_t(crc >> (8 * i));
        // an error, or (a flip the checks cannot see, e.g. a height within
        // the range) a summary: never a crash
        refused += !summary_error(bad).empty();
    }
    EXPECT_GT(refused, 300);
}

TEST(BlockSummary, TruncationsAtEverySectionBoundaryAreErrors)
{
    const Model model = voxel_model(11, 9, 10, 20, 2);
    StacksV2Options options;
    options.block_size = 4;
    const auto bytes = encode_stacks_v2(model, options);
    const auto [begin, end] = summary_section(bytes);
    const size_t materials_end = STACKS_V2_HEADER_SIZE + 8 * model.materials().size();
    for (const size_t size :
         {size_t(10), size_t(STACKS_V2_HEADER_SIZE - 1), size_t(STACKS_V2_HEADER_SIZE),
          materials_end, begin - 1, begin, begin + 3, end - 16, end - 1, end, end + 24,
          bytes.size() - 1}) {
        const std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + long(size));
        EXPECT_NE(summary_error(cut), "") << size;
    }
    // a section that claims more bytes than lie before the table
    std::vector<uint8_t> bad = bytes;
    for (int i = 0; i < 8; ++i)
        bad[end - 8 + size_t(i)] = uint8_t(uint64_t(end) >> (8 * i));
    EXPECT_NE(summary_error(bad).find("size"), std::string::npos) << summary_error(bad);
}
