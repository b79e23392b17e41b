/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The `ranges` member: written beside the stacks, read back as
 *            the column ranges of the decoded model; a paged model opened
 *            from it decodes no block; a stale member ignored, a damaged
 *            one refused
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>

#include <gtest/gtest.h>
#include <zstd.h>

#include "format/byte_io.hpp"
#include "format/column_ranges_file.hpp"
#include "format/format.hpp"
#include "model/column_ranges.hpp"
#include "util/error.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

bool same(const std::vector<ZRange> &a, const std::vector<ZRange> &b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].empty() != b[i].empty() ||
            (!a[i].empty() && (a[i].low != b[i].low || a[i].high != b[i].high)))
            return false;
    return true;
}

bool same(const ColumnRangeArray &a, const std::vector<ZRange> &b)
{
    return same(a.widened_all(), b);
}

Paging roomy()
{
    Paging paging;
    paging.budget_bytes = uint64_t(1) << 30;
    return paging;
}

} // namespace

TEST(ColumnRangesFile, PagedModelOpensFromItWithoutDecoding)
{
    const Model model = sbrt_test::model_with_air_columns(31); // and columns of air
    const std::vector<ZRange> want = column_ranges(model);
    size_t empty = 0;
    for (const ZRange &r : want)
        empty += r.empty();
    ASSERT_GT(empty, 0u); // columns of nothing but air are among them
    const std::string dir = sbrt_test::temp_dir("ranges") + "/m";
    write_sbrt(dir, model, "test");
    const std::optional<Model> paged = read_sbrt_paged(dir, roomy());
    ASSERT_TRUE(paged);
    EXPECT_TRUE(same(paged->pages()->column_ranges(), want));
    // a voxel model's ranges held as its member holds them: u16 pairs
    EXPECT_TRUE(paged->pages()->column_ranges().is_compact());
    EXPECT_EQ(paged->pages()->column_ranges().bytes(), model.frame().cells() * 4);
    EXPECT_EQ(paged->pages()->figures().decodes, 0u); // read from the member
    EXPECT_EQ(paged->pages()->highest_top_local(), highest_top_local(model));

    // a member made from other stacks is ignored: the blocks are read
    const Model other = sbrt_test::build_model(sbrt_test::random_voxels(32, 70, 90, 24, 5));
    const std::string other_dir = dir + "_other";
    write_sbrt(other_dir, other, "test");
    const std::vector<uint8_t> member = read_file_bytes(dir + "/ranges");
    sbrt_test::put_file_bytes(dir + "/ranges", read_file_bytes(other_dir + "/ranges"));
    const std::optional<Model> stale = read_sbrt_paged(dir, roomy());
    ASSERT_TRUE(stale);
    EXPECT_TRUE(same(stale->pages()->column_ranges(), want));
    // read from the blocks as u16 pairs, as the summary says they are
    EXPECT_TRUE(stale->pages()->column_ranges().is_compact());
    EXPECT_GT(stale->pages()->figures().decodes, 0u);

    // a damaged member is refused, naming it
    for (const size_t at : {size_t(3), size_t(60), member.size() - 2}) {
        std::vector<uint8_t> damaged = member;
        damaged[at] ^= 0x20;
        sbrt_test::put_file_bytes(dir + "/ranges", damaged);
        try {
            read_sbrt_paged(dir, roomy());
            // a flipped stamp reads as a member of other stacks: ignored
            EXPECT_TRUE(at >= 20 && at < 40) << at;
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("ranges"), std::string::npos) << e.what();
        }
    }
    sbrt_test::put_file_bytes(dir + "/ranges", member);
    EXPECT_NO_THROW(read_sbrt_paged(dir, roomy()));
}

TEST(ColumnRangesFile, RangesOfContinuousTopsRoundTrip)
{
    // tops off the voxel boundaries (horizons) are stored as f32 pairs
    const Frame f = sbrt_test::unit_frame(2, 3, 10);
    std::vector<ZRange> ranges(f.cells());
    ranges[0] = {0.0f, 2.5f};
    ranges[1] = {1.25f, 9.75f};
    ranges[4] = {3.0f, 4.0f};
    const StacksStamp stamp{1234, 56, 789};
    const std::vector<uint8_t> bytes = encode_column_ranges(ranges, f, stamp);
    const auto back = decode_column_ranges(bytes.data(), bytes.size(), "r", f, stamp);
    ASSERT_TRUE(back);
    EXPECT_TRUE(same(*back, ranges));
    EXPECT_FALSE(back->is_compact()); // floats where the member holds floats
    // a range above the depths is refused
    ranges[4] = {3.0f, 11.0f};
    const std::vector<uint8_t> high = encode_column_ranges(ranges, f, stamp);
    EXPECT_THROW(decode_column_ranges(high.data(), high.size(), "r", f, stamp), Error);
}

TEST(ColumnRangesFile, BandsTurnToF32PairsWhereALaterRangeNeedsThem)
{
    // voxel boundaries first (packed as u16 pairs), a continuous top later
    const Frame f = sbrt_test::unit_frame(3, 2, 10);
    std::vector<ZRange> ranges(f.cells());
    ranges[0] = {0.0f, 2.0f};
    ranges[2] = {3.0f, 9.0f};
    ranges[5] = {1.0f, 7.5f};
    const StacksStamp stamp{1, 2, 3};
    ColumnRangesEncoder encoder(f);
    for (int row = 0; row < f.rows; ++row)
        encoder.add(std::vector<ZRange>(ranges.begin() + 2 * row, ranges.begin() + 2 * row + 2));
    const std::vector<uint8_t> bytes = encoder.finish(stamp);
    EXPECT_EQ(bytes, encode_column_ranges(ranges, f, stamp));
    const auto back = decode_column_ranges(bytes.data(), bytes.size(), "r", f, stamp);
    ASSERT_TRUE(back);
    EXPECT_TRUE(same(*back, ranges));
    // a range too many, or one missing, is refused
    EXPECT_THROW(encoder.add({ZRange{}}), Error);
    ColumnRangesEncoder short_of_one(f);
    short_of_one.add(std::vector<ZRange>(5));
    EXPECT_THROW(short_of_one.finish(stamp), Error);
}

TEST(ColumnRangesFile, MembersOfOneFrameAsWrittenBeforeAreRead)
{
    // members are written a zstd frame every 64 rows (decompressed in
    // parallel); those written before held the whole member in one frame
    const Model model = sbrt_test::build_model(sbrt_test::random_voxels(33, 150, 40, 12, 4));
    const Frame &f = model.frame();
    const std::vector<ZRange> want = column_ranges(model);
    const StacksStamp stamp{5, 6, 7};
    const std::vector<uint8_t> framed = encode_column_ranges(want, f, stamp);
    constexpr size_t HEADER = 52;
    const uint8_t *packed = framed.data() + HEADER;
    const size_t packed_size = framed.size() - HEADER;
    EXPECT_LT(ZSTD_findFrameCompressedSize(packed, packed_size), packed_size); // three frames
    std::vector<uint8_t> raw(f.cells() * 4);
    ASSERT_EQ(ZSTD_decompress(raw.data(), raw.size(), packed, packed_size), raw.size());
    std::vector<uint8_t> one(ZSTD_compressBound(raw.size()));
    one.resize(ZSTD_compress(one.data(), one.size(), raw.data(), raw.size(), 3));
    std::vector<uint8_t> older_bytes(framed.begin(), framed.begin() + HEADER);
    for (int i = 0; i < 8; ++i) // the compressed size, then its crc
        older_bytes[40 + i] = uint8_t(uint64_t(one.size()) >> (8 * i));
    const uint32_t crc = crc32_of(one.data(), one.size());
    for (int i = 0; i < 4; ++i)
        older_bytes[48 + i] = uint8_t(crc >> (8 * i));
    older_bytes.insert(older_bytes.end(), one.begin(), one.end());
    const std::vector<uint8_t> &older = older_bytes;
    for (const std::vector<uint8_t> *member : {&framed, &older}) {
        const auto back = decode_column_ranges(member->data(), member->size(), "r", f, stamp, 3);
        ASSERT_TRUE(back);
        EXPECT_TRUE(same(*back, want));
    }
    // frames that do not hold whole rows of the grid are refused
    const Frame wider = sbrt_test::unit_frame(f.rows * 2, f.cols / 2, f.depths);
    EXPECT_THROW(decode_column_ranges(framed.data(), framed.size(), "r", wider, stamp), Error);
}

TEST(ColumnRangesFile, CompactRangesReadAsTheWideOnes)
{
    // every range a u16 pair holds (air, a column from 0, the top voxel
    // boundary) reads back from CompactRanges as it was; one off a voxel
    // boundary, or above 65535, does not fit them
    std::vector<ZRange> ranges(6);
    ranges[1] = {0.0f, 3.0f};
    ranges[2] = {2.0f, 65535.0f};
    ranges[4] = {7.0f, 8.0f};
    CompactRanges compact(ranges.size(), CompactRange{});
    for (size_t i = 0; i < ranges.size(); ++i) {
        ASSERT_TRUE(fits_compact_range(ranges[i])) << i;
        if (!ranges[i].empty())
            compact[i] = {uint16_t(ranges[i].low), uint16_t(ranges[i].high)};
    }
    const ColumnRangeArray held(std::move(compact));
    ASSERT_TRUE(held.is_compact());
    EXPECT_EQ(held.bytes(), 6u * 4);
    EXPECT_TRUE(same(held, ranges));
    for (size_t i = 0; i < ranges.size(); ++i) // an empty one reads as ZRange{}
        EXPECT_EQ(held[i].empty(), ranges[i].empty()) << i;
    EXPECT_FALSE(fits_compact_range({1.5f, 3.0f}));
    EXPECT_FALSE(fits_compact_range({0.0f, 65536.0f}));
    const ColumnRangeArray wide(ranges);
    EXPECT_FALSE(wide.is_compact());
    EXPECT_EQ(wide.bytes(), 6u * 8);
    EXPECT_TRUE(same(wide, ranges));
}
