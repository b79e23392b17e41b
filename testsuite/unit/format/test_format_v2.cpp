/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Format v2: exact round trips for voxel and horizon models in
 *            any block size and thread count, the narrowest widths, a
 *            later minor version read by prefix, v1 still read, the memory
 *            limit, corrupt blocks
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/byte_io.hpp"
#include "format/format.hpp"
#include "format/stacks_fields.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

/// The same model: frame, materials, index and every interval.
void expect_same(const Model &a, const Model &b)
{
    EXPECT_EQ(encode_stacks_v1(a), encode_stacks_v1(b));
    ASSERT_EQ(a.materials().size(), b.materials().size());
    for (size_t i = 1; i < a.materials().size(); ++i)
        EXPECT_EQ(a.materials()[i].label, b.materials()[i].label) << i;
}

Model decode(const std::vector<uint8_t> &bytes, unsigned threads = 0)
{
    ReadOptions options;
    options.threads = threads;
    return decode_stacks(bytes.data(), bytes.size(), "v2", nullptr, options);
}

std::string message_of(const std::vector<uint8_t> &bytes, const ReadOptions &options = {})
{
    try {
        decode_stacks(bytes.data(), bytes.size(), "v2", nullptr, options);
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

/// Rewrites the header checksum after an edit of the header.
void reseal_header(std::vector<uint8_t> &bytes, uint32_t header_size)
{
    const uint32_t crc = crc32_of(bytes.data(), header_size - 4);
    for (int i = 0; i < 4; ++i)
        bytes[header_size - 4 + i] = uint8_t(crc >> (8 * i));
}

uint64_t field(const std::vector<uint8_t> &b, size_t at, int n)
{
    uint64_t v = 0;
    for (int i = 0; i < n; ++i)
        v |= uint64_t(b[at + size_t(i)]) << (8 * i);
    return v;
}

void set_field(std::vector<uint8_t> &b, size_t at, uint64_t v, int n)
{
    for (int i = 0; i < n; ++i)
        b[at + size_t(i)] = uint8_t(v >> (8 * i));
}

// offsets in the 2.0 header
constexpr size_t AT_MINOR = 10, AT_HEADER_SIZE = 12, AT_REQUIRED = 16, AT_OPTIONAL = 20,
                 AT_WIDTHS = 112, AT_MATERIALS = 116, AT_TABLE = 124, AT_END = 132,
                 AT_CRC_TABLE = 144;

} // namespace

TEST(FormatV2, VoxelModelsRoundTripInAnyBlockSizeAndThreadCount)
{
    for (const auto &[rows, cols, depths] : {std::tuple{1, 1, 1}, {6, 7, 20}, {33, 65, 90}}) {
        const Model model =
            sbrt_test::build_model(sbrt_test::random_voxels(rows * 31 + cols, rows, cols, depths));
        for (int block : {1, 3, 16, 64}) {
            StacksV2Options options;
            options.block_size = block;
            const auto bytes = encode_stacks_v2(model, options);
            for (unsigned threads : {1u, 3u})
                expect_same(decode(bytes, threads), model);
            // the same bytes whatever the writer's thread count
            options.threads = 1;
            EXPECT_EQ(encode_stacks_v2(model, options), bytes) << rows << "x" << cols;
        }
    }
}

TEST(FormatV2, VoxelTopsAreU16AndContinuousTopsStayFloat)
{
    const Model voxels = sbrt_test::build_model(sbrt_test::random_voxels(3, 9, 8, 50));
    EXPECT_EQ(widths_for(voxels).tops, TopEncoding::VoxelBoundaries);
    const Model horizons = sbrt_test::float_model(10, 13, 6, 5);
    EXPECT_EQ(widths_for(horizons).tops, TopEncoding::Float32);
    expect_same(decode(encode_stacks_v2(horizons)), horizons);
}

TEST(FormatV2, WidthsGrowOnlyWhereTheModelNeedsThem)
{
    const Model small = sbrt_test::float_model(4, 4, 3, 5);
    EXPECT_EQ(widths_for(small).count_bytes, 1);
    EXPECT_EQ(widths_for(small).material_bytes, 1);
    const Model many = sbrt_test::float_model(5, 7, 300, 400); // stacks > 255, 401 materials
    EXPECT_EQ(widths_for(many).count_bytes, 2);
    EXPECT_EQ(widths_for(many).material_bytes, 2);
    expect_same(decode(encode_stacks_v2(many)), many);
}

TEST(FormatV2, LayeredVoxelsTakeUnderTwoBytesAnInterval)
{
    // strata of slowly varying thickness, as in a lithology model
    sbrt_test::Voxels v = sbrt_test::random_voxels(1, 80, 90, 120);
    for (int r = 0; r < 80; ++r)
        for (int c = 0; c < 90; ++c)
            for (int z = 0; z < 120; ++z) {
                const int layer = (z + (r / 9 + c / 11) % 4) / 12;
                v.classes[(size_t(z) * 80 + r) * 90 + c] = z > 110 - (r + c) % 3 ? NULL_CLASS
                                                                                  : 1 + layer % 6;
            }
    const Model model = sbrt_test::build_model(v);
    const auto bytes = encode_stacks_v2(model);
    const double per_interval = double(bytes.size()) / double(model.intervals().size());
    EXPECT_LT(per_interval, 2.0);
    EXPECT_LT(bytes.size() * 4, encode_stacks_v1(model).size());
    expect_same(decode(bytes), model);
}

TEST(FormatV2, EvenUncorrelatedColumnsTakeUnderTwoBytesAnInterval)
{
    // the worst case: every column random runs of random classes, no
    // neighbour alike (real lithology is far more alike)
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(5, 100, 100, 313, 9));
    const auto bytes = encode_stacks_v2(model);
    EXPECT_LT(double(bytes.size()) / double(model.intervals().size()), 2.0);
}

TEST(FormatV2, LaterMinorVersionWithMoreFieldsIsReadByPrefix)
{
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(5, 9, 10, 30));
    const auto bytes = encode_stacks_v2(model);
    // a 2.3 file: 16 more header bytes before the checksum, an optional
    // feature this reader does not know
    const uint32_t grow = 16, size = STACKS_V2_HEADER_SIZE + grow;
    std::vector<uint8_t> later(bytes.begin(), bytes.begin() + STACKS_V2_HEADER_SIZE - 4);
    later.insert(later.end(), grow + 4, 0xab);
    later.insert(later.end(), bytes.begin() + STACKS_V2_HEADER_SIZE, bytes.end());
    set_field(later, AT_MINOR, 3, 2);
    set_field(later, AT_HEADER_SIZE, size, 4);
    set_field(later, AT_OPTIONAL, 0x10, 4);
    for (size_t at : {AT_MATERIALS, AT_TABLE, AT_END})
        set_field(later, at, field(later, at, 8) + grow, 8);
    // block offsets move too: the table is rewritten and resealed
    const size_t table = size_t(field(later, AT_TABLE, 8));
    for (size_t e = table; e < later.size(); e += 24)
        set_field(later, e, field(later, e, 8) + grow, 8);
    set_field(later, AT_CRC_TABLE, crc32_of(later.data() + table, later.size() - table), 4);
    reseal_header(later, size);
    expect_same(decode(later), model);

    // a required feature it does not know: refused, saying why
    set_field(later, AT_REQUIRED, 0x4, 4);
    reseal_header(later, size);
    const std::string message = message_of(later);
    EXPECT_NE(message.find("newer r3.sbrt"), std::string::npos) << message;
    EXPECT_NE(message.find("2.3"), std::string::npos) << message;
}

TEST(FormatV2, VersionOneDirectoriesStayReadable)
{
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(8, 7, 9, 25));
    const std::string dir = sbrt_test::temp_dir("v1") + "/m";
    {
        AtomicDirectory out(dir);
        out.write_file("stacks", encode_stacks_v1(model));
        out.commit();
    }
    expect_same(read_sbrt(dir), model);
    write_sbrt(dir, model, "v2\n");
    const std::vector<uint8_t> stacks = read_file_bytes(dir + "/stacks");
    EXPECT_EQ(stacks_major_version(stacks.data(), stacks.size()), 2);
    EXPECT_EQ(stacks, encode_stacks_v2(model));
    expect_same(read_sbrt(dir), model);
    remove_tree(dir.substr(0, dir.rfind('/')));
}

/// `model` in blocks of 8 x 8 cells, with the optional features given.
std::vector<uint8_t> in_blocks_of_8(const Model &model, uint32_t optional_features = 0)
{
    StacksV2Options options;
    options.block_size = 8;
    options.optional_features = optional_features;
    return encode_stacks_v2(model, options);
}

TEST(FormatV2, AnAreaReadsOnlyTheBlocksItMeets)
{
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(12, 40, 50, 30));
    const Frame &f = model.frame(); // 10 x 5 map units a cell
    const auto bytes = in_blocks_of_8(model);
    ReadReport report;
    ReadOptions read;
    read.report = &report;
    // cells of rows 12..19 and cols 20..29 (edges inside cells)
    read.area = MapArea{f.north - 12 * 10 - 3, f.north - 20 * 10 + 3, f.west + 30 * 5 - 1,
                        f.west + 20 * 5 + 1};
    const Model part = decode_stacks(bytes.data(), bytes.size(), "area", nullptr, read);
    // grown by one cell: rows 11..20 and cols 19..30, in blocks of 8: rows
    // 8..23, cols 16..31 (2 x 2 of 5 x 7 blocks)
    EXPECT_EQ(report.blocks, 35u);
    EXPECT_EQ(report.blocks_read, 4u);
    for (int r = 0; r < f.rows; ++r)
        for (int c = 0; c < f.cols; ++c) {
            const uint64_t cell = model.cell_index(r, c);
            const bool read_block = r >= 8 && r < 24 && c >= 16 && c < 32;
            ASSERT_EQ(part.stack_size(cell), read_block ? model.stack_size(cell) : 0u)
                << r << "," << c;
            for (uint32_t i = 0; i < part.stack_size(cell); ++i) {
                const Interval a = part.intervals()[part.stack_begin(cell) + i];
                const Interval b = model.intervals()[model.stack_begin(cell) + i];
                ASSERT_EQ(a.material, b.material);
                ASSERT_EQ(a.top, b.top);
            }
        }
    // an area off the model reads nothing and leaves every stack empty
    read.area = MapArea{f.north + 100, f.north + 50, f.east, f.west};
    const Model none = decode_stacks(bytes.data(), bytes.size(), "area", nullptr, read);
    EXPECT_EQ(report.blocks_read, 0u);
    EXPECT_TRUE(none.intervals().empty());
    // a v1 file is read whole
    const auto v1 = encode_stacks_v1(model);
    EXPECT_EQ(decode_stacks(v1.data(), v1.size(), "v1", nullptr, read).intervals().size(),
              model.intervals().size());
    EXPECT_EQ(report.blocks, 0u);
}

TEST(FormatV2, PointsReadOnlyTheirCellsFromTheBlocksThatHoldThem)
{
    // voxel tops (held compact) and continuous tops (held wide)
    for (const Model &model : {sbrt_test::build_model(sbrt_test::random_voxels(12, 40, 50, 30)),
                               sbrt_test::float_model(40, 50, 6, 5)}) {
        const Frame &f = model.frame();
        const auto bytes = in_blocks_of_8(model);
        ReadReport report;
        ReadOptions read;
        read.report = &report;
        // two points in one block (rows 12, 13 of cols 20, 21), one on a
        // block's corner cell (row 31, col 47), one outside the model
        const auto at = [&](int row, int col) {
            return std::array<double, 2>{f.west + (col + 0.5) * f.ew_res(),
                                         f.north - (row + 0.5) * f.ns_res()};
        };
        read.points = std::vector<std::array<double, 2>>{
            at(12, 20), at(13, 21), at(31, 47), {f.east + 1, f.north - 1}};
        const Model part = decode_stacks(bytes.data(), bytes.size(), "points", nullptr, read);
        EXPECT_EQ(report.blocks, 35u);
        EXPECT_EQ(report.blocks_read, 2u);
        uint64_t kept = 0;
        for (int r = 0; r < f.rows; ++r)
            for (int c = 0; c < f.cols; ++c) {
                const uint64_t cell = model.cell_index(r, c);
                const bool wanted = (r == 12 && c == 20) || (r == 13 && c == 21) ||
                                    (r == 31 && c == 47);
                ASSERT_EQ(part.stack_size(cell), wanted ? model.stack_size(cell) : 0u)
                    << r << "," << c;
                kept += part.stack_size(cell);
                for (uint32_t i = 0; i < part.stack_size(cell); ++i) {
                    const Interval a = part.intervals()[part.stack_begin(cell) + i];
                    const Interval b = model.intervals()[model.stack_begin(cell) + i];
                    ASSERT_EQ(a.material, b.material);
                    ASSERT_EQ(a.top, b.top);
                }
            }
        EXPECT_GT(kept, 2u);
        EXPECT_EQ(part.intervals().size(), kept); // nothing held for the others
        // with an area too: only the points inside it
        read.area = MapArea{f.north, f.north - 20 * f.ns_res(), f.east, f.west};
        const Model north = decode_stacks(bytes.data(), bytes.size(), "points", nullptr, read);
        EXPECT_EQ(report.blocks_read, 1u);
        EXPECT_EQ(north.stack_size(model.cell_index(31, 47)), 0u);
        EXPECT_EQ(north.stack_size(model.cell_index(12, 20)), model.stack_size(model.cell_index(12, 20)));
        // no point on the model: nothing read
        read.area.reset();
        read.points = std::vector<std::array<double, 2>>{{f.west - 1, f.north - 1}};
        const Model none = decode_stacks(bytes.data(), bytes.size(), "points", nullptr, read);
        EXPECT_EQ(report.blocks_read, 0u);
        EXPECT_TRUE(none.intervals().empty());
        // an SBRT with property channels: every stack of the blocks read
        const auto with_channels = in_blocks_of_8(model, V2_OPTIONAL_CHANNELS);
        read.points = std::vector<std::array<double, 2>>{at(12, 20)};
        const Model block = decode_stacks(with_channels.data(), with_channels.size(), "points",
                                          nullptr, read);
        EXPECT_EQ(report.blocks_read, 1u);
        for (int r = 8; r < 16; ++r)
            for (int c = 16; c < 24; ++c)
                ASSERT_EQ(block.stack_size(model.cell_index(r, c)),
                          model.stack_size(model.cell_index(r, c)));
        EXPECT_EQ(block.stack_size(model.cell_index(16, 20)), 0u);
    }
}

TEST(FormatV2, ModelLargerThanTheMemoryLimitIsRefusedFirst)
{
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(9, 20, 20, 40));
    ReadOptions options;
    options.memory_limit = 1024;
    const std::string message = message_of(encode_stacks_v2(model), options);
    EXPECT_NE(message.find("MiB of memory"), std::string::npos) << message;
}

TEST(FormatV2, CorruptBlocksWithValidChecksumsNeverCrash)
{
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(10, 12, 12, 40));
    StacksV2Options options;
    options.block_size = 5;
    const auto bytes = encode_stacks_v2(model, options);
    const size_t table = size_t(field(bytes, AT_TABLE, 8));
    std::mt19937 rng(11);
    std::vector<uint8_t> bad;
    for (int trial = 0; trial < 300; ++trial) {
        bad = bytes;
        const size_t entry = table + 24 * (rng() % ((bad.size() - table) / 24));
        const size_t offset = size_t(field(bad, entry, 8));
        const size_t compressed = size_t(field(bad, entry + 8, 4));
        bad[offset + rng() % compressed] ^= uint8_t(1u << (rng() % 8));
        // the block's own checksum and the table's made to match
        set_field(bad, entry + 20, crc32_of(bad.data() + offset, compressed), 4);
        set_field(bad, AT_CRC_TABLE, crc32_of(bad.data() + table, bad.size() - table), 4);
        reseal_header(bad, STACKS_V2_HEADER_SIZE);
        // an error or, where the flip decodes to other valid stacks, a
        // model: never a crash (the sanitizer build runs this too)
        message_of(bad);
    }
    // a grid of 2^31 - 1 rows: its blocks are counted without overflow
    bad = bytes;
    set_field(bad, 72, 0x7fffffff, 4);
    set_field(bad, 76, 1, 4);
    reseal_header(bad, STACKS_V2_HEADER_SIZE);
    EXPECT_NE(message_of(bad), "");
    // field widths no writer makes
    bad = bytes;
    set_field(bad, AT_WIDTHS, 3, 1);
    reseal_header(bad, STACKS_V2_HEADER_SIZE);
    EXPECT_NE(message_of(bad).find("widths"), std::string::npos);
}
