/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The reader rejects truncated, corrupt, foreign and future files
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/byte_io.hpp"
#include "format/format.hpp"
#include "test_support.hpp"
#include "builders/voxel_builder.hpp"

using namespace sbrt;

namespace {

Model sample_model()
{
    return sbrt_test::build_model(sbrt_test::random_voxels(21, 6, 7, 20));
}

std::vector<uint8_t> sample_file()
{
    return encode_stacks_v1(sample_model());
}

/// The sample in both formats (v2 in blocks of 4 cells a side: several).
std::vector<std::vector<uint8_t>> sample_files()
{
    StacksV2Options blocks;
    blocks.block_size = 4;
    return {sample_file(), encode_stacks_v2(sample_model(), blocks)};
}

std::string message_of(const std::vector<uint8_t> &bytes)
{
    try {
        decode_stacks(bytes.data(), bytes.size(), "f");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

/// Rewrites the header checksum so that a deliberately edited header field
/// reaches the later checks.
void reseal_header(std::vector<uint8_t> &bytes)
{
    const uint32_t crc = crc32_of(bytes.data(), STACKS_V1_HEADER_SIZE - 4);
    for (int i = 0; i < 4; ++i)
        bytes[STACKS_V1_HEADER_SIZE - 4 + i] = uint8_t(crc >> (8 * i));
}

} // namespace

TEST(Format, ValidFileDecodes)
{
    const auto bytes = sample_file();
    EXPECT_EQ(message_of(bytes), "");
}

TEST(Format, EveryTruncationThrows)
{
    for (const auto &bytes : sample_files())
    for (size_t n = 0; n < bytes.size(); n += 1 + n / 50) {
        std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + n);
        EXPECT_NE(message_of(cut), "") << "truncated to " << n;
    }
}

TEST(Format, BitFlipsAnywhereThrow)
{
    std::mt19937 rng(4);
    for (const auto &bytes : sample_files())
    for (int trial = 0; trial < 400; ++trial) {
        auto bad = bytes;
        const size_t at = rng() % bad.size();
        bad[at] ^= uint8_t(1u << (rng() % 8));
        EXPECT_NE(message_of(bad), "") << "flip at byte " << at;
    }
}

TEST(Format, TrailingGarbageThrows)
{
    for (auto bytes : sample_files()) {
        bytes.push_back(0);
        EXPECT_NE(message_of(bytes).find("describes"), std::string::npos);
    }
}

TEST(Format, ForeignAndEmptyFilesThrowClearly)
{
    EXPECT_NE(message_of({}).find("magic"), std::string::npos);
    const std::string text = "This is a GRASS cellhd file\nproj: 99\n";
    EXPECT_NE(message_of({text.begin(), text.end()}).find("magic"),
              std::string::npos);
}

TEST(Format, FutureVersionIsNamed)
{
    for (auto bytes : sample_files()) {
        bytes[8] = 7; // version field follows the 8-byte magic
        EXPECT_NE(message_of(bytes).find("version 7"), std::string::npos);
    }
}

TEST(Format, InvariantsAreCheckedAfterChecksums)
{
    // a material index beyond the table, with valid checksums everywhere
    auto bytes = sample_file();
    ByteReader head(bytes.data(), bytes.size(), "t");
    head.seek(8 + 4 + 4 + 48 + 20 + 4 + 8 + 16);
    const uint64_t at_intervals = head.u64();
    bytes[at_intervals] = 0xff; // low byte of the first interval's material
    const uint32_t crc = crc32_of(bytes.data() + at_intervals,
                                  bytes.size() - at_intervals);
    const size_t crc_at = STACKS_V1_HEADER_SIZE - 8;
    for (int i = 0; i < 4; ++i)
        bytes[crc_at + i] = uint8_t(crc >> (8 * i));
    reseal_header(bytes);
    EXPECT_NE(message_of(bytes).find("out of range"), std::string::npos)
        << message_of(bytes);
}

TEST(Format, HugeCountsAreRejectedBeforeAllocation)
{
    auto bytes = sample_file();
    // interval count (u64 after the material count) set to 2^40
    const size_t at = 8 + 4 + 4 + 48 + 20 + 4;
    for (int i = 0; i < 8; ++i)
        bytes[at + i] = i == 5 ? 1 : 0;
    reseal_header(bytes);
    EXPECT_NE(message_of(bytes).find("exceeds"), std::string::npos);
}

TEST(Format, MissingDirectoryIsAnError)
{
    EXPECT_THROW(read_sbrt("/nonexistent/sbrt/none"), Error);
}

TEST(Format, ReadOfV1MapsTheIntervalsWithoutACopy)
{
    const auto v = sbrt_test::random_voxels(41, 9, 11, 30);
    const Model written = sbrt_test::build_model(v);
    const std::string dir = sbrt_test::temp_dir("mapped") + "/m";
    {
        // a v1 SBRT (v2 blocks are decompressed into memory of their own)
        AtomicDirectory out(dir);
        out.write_file("stacks", encode_stacks_v1(written));
        out.commit();
    }
    auto same = [&](const Model &m) {
        ASSERT_EQ(m.intervals().size(), written.intervals().size());
        for (size_t i = 0; i < m.intervals().size(); ++i) {
            ASSERT_EQ(m.intervals()[i].material, written.intervals()[i].material) << i;
            ASSERT_EQ(m.intervals()[i].top, written.intervals()[i].top) << i;
        }
    };
    std::optional<Model> read(read_sbrt(dir));
    EXPECT_TRUE(read->intervals().is_view());
    same(*read);
    // a copy shares the mapping and outlives the model it was copied from
    const Model copy = *read;
    read.reset();
    EXPECT_TRUE(copy.intervals().is_view());
    same(copy);
    // replacing the SBRT (atomically, as every writer here does) leaves
    // the mapped model as it was read
    write_sbrt(dir, sbrt_test::build_model(sbrt_test::random_voxels(42, 9, 11, 30)), "new\n");
    same(copy);
    // decoded from bytes nobody keeps: a copy of its own
    const std::vector<uint8_t> bytes = encode_stacks_v1(written);
    EXPECT_FALSE(decode_stacks(bytes.data(), bytes.size(), "bytes").intervals().is_view());
}

TEST(Format, ValidationListsTheFirstProblemsInCellOrderAndCountsAll)
{
    // problems spread over the whole grid (validation runs on all cores in
    // runs of cells): the first eight listed by cell, all counted
    const Model good = sbrt_test::build_model(sbrt_test::random_voxels(11, 120, 140, 12, 5));
    const Frame &f = good.frame();
    auto corrupt = [&](const std::vector<uint64_t> &cells) {
        Intervals wide(good.intervals().size());
        for (size_t i = 0; i < wide.size(); ++i)
            wide[i] = good.intervals()[i];
        for (uint64_t c : cells)
            wide[good.index().range(c).begin].material = 999; // beyond the table
        return Model(f, good.materials(), good.index(), IntervalArray(std::move(wide)));
    };
    std::vector<uint64_t> cells;
    for (uint64_t c = f.cells() - 1; cells.size() < 20; c -= f.cells() / 23)
        if (good.index().size(c) > 0)
            cells.push_back(c);
    std::sort(cells.begin(), cells.end());
    std::string message;
    try {
        corrupt(cells).validate();
    }
    catch (const Error &e) {
        message = e.what();
    }
    EXPECT_NE(message.find("20 problem(s)"), std::string::npos) << message;
    size_t at = 0;
    for (size_t k = 0; k < cells.size(); ++k) {
        const size_t found = message.find("cell " + std::to_string(cells[k]) + ":");
        if (k < 8) {
            ASSERT_NE(found, std::string::npos) << k << ": " << message;
            EXPECT_GT(found, at) << "in cell order";
            at = found;
        }
        else {
            EXPECT_EQ(found, std::string::npos) << "only the first eight are listed";
        }
    }
    EXPECT_NO_THROW(good.validate());
}
