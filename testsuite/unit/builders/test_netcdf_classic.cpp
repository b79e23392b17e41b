/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Classic netCDF headers as untrusted bytes: the length they
 *            declare (CDF-1, CDF-2, CDF-5, records, streaming), truncated
 *            files, and hostile counts, lengths and ids (issue 28, item 6)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "builders/netcdf_classic.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

/// \brief Writes a classic header field by field, big-endian, as the
/// netCDF format specification lays it out.
class Header {
public:
    explicit Header(int version, uint64_t numrecs = 0) : version_(version)
    {
        bytes_ = {'C', 'D', 'F', uint8_t(version)};
        non_neg(numrecs);
    }
    Header &u32(uint64_t v) { return be(v, 4); }
    Header &non_neg(uint64_t v) { return be(v, version_ == 5 ? 8 : 4); }
    Header &offset(uint64_t v) { return be(v, version_ == 1 ? 4 : 8); }
    Header &name(const std::string &s)
    {
        non_neg(s.size());
        bytes_.insert(bytes_.end(), s.begin(), s.end());
        while (bytes_.size() % 4)
            bytes_.push_back(0);
        return *this;
    }
    Header &absent() { return u32(0).non_neg(0); }
    /// dimension list of (name, length)
    Header &dims(const std::vector<std::pair<std::string, uint64_t>> &d)
    {
        u32(10).non_neg(d.size());
        for (const auto &[n, len] : d)
            name(n).non_neg(len);
        return *this;
    }
    /// a variable without attributes; `begin` where its data starts
    Header &var(const std::string &n, const std::vector<uint64_t> &dimids, uint32_t type,
                uint64_t vsize, uint64_t begin)
    {
        name(n).non_neg(dimids.size());
        for (uint64_t id : dimids)
            non_neg(id);
        return absent().u32(type).non_neg(vsize).offset(begin);
    }
    size_t size() const { return bytes_.size(); }
    const std::vector<uint8_t> &bytes() const { return bytes_; }

private:
    Header &be(uint64_t v, int n)
    {
        for (int i = n - 1; i >= 0; --i)
            bytes_.push_back(uint8_t(v >> (8 * i)));
        return *this;
    }
    int version_;
    std::vector<uint8_t> bytes_;
};

ClassicLayout layout_of(const Header &h, uint64_t file_bytes)
{
    const auto layout = read_classic_layout(h.bytes().data(), h.size(), file_bytes);
    EXPECT_TRUE(layout.has_value());
    return layout.value_or(ClassicLayout());
}

std::string error_of(const Header &h, uint64_t file_bytes)
{
    try {
        const auto layout = read_classic_layout(h.bytes().data(), h.size(), file_bytes);
        if (layout)
            check_classic_length(*layout, file_bytes, "f.nc");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

/// lithok(x, y, z) short after x(x), y(y), z(z) int, as ncgen lays it out
/// (variable data after the header, in order): CDF-1 or CDF-2.
Header geotop_header(int version, uint64_t nx, uint64_t ny, uint64_t nz, uint64_t &data_end)
{
    // begin offsets depend on the header's own length: lay it out twice
    uint64_t header = 0;
    Header h(version);
    for (int pass = 0; pass < 2; ++pass) {
        h = Header(version);
        h.dims({{"x", nx}, {"y", ny}, {"z", nz}}).absent().u32(11).non_neg(4);
        uint64_t at = header;
        auto place = [&](const std::string &n, std::vector<uint64_t> ids, uint32_t type,
                         uint64_t bytes) {
            h.var(n, ids, type, (bytes + 3) / 4 * 4, at);
            at += (bytes + 3) / 4 * 4;
            data_end = at - (bytes + 3) / 4 * 4 + bytes;
        };
        place("x", {0}, 4, 4 * nx);
        place("y", {1}, 4, 4 * ny);
        place("z", {2}, 4, 4 * nz);
        place("lithok", {0, 1, 2}, 3, 2 * nx * ny * nz);
        header = h.size();
    }
    return h;
}

} // namespace

TEST(NetcdfClassic, MagicOfTheThreeVersionsOnly)
{
    const uint8_t cdf1[] = {'C', 'D', 'F', 1}, cdf5[] = {'C', 'D', 'F', 5},
                  cdf3[] = {'C', 'D', 'F', 3}, hdf[] = {0x89, 'H', 'D', 'F'};
    EXPECT_TRUE(is_classic_netcdf(cdf1, 4));
    EXPECT_TRUE(is_classic_netcdf(cdf5, 4));
    EXPECT_FALSE(is_classic_netcdf(cdf3, 4));
    EXPECT_FALSE(is_classic_netcdf(hdf, 4));
    EXPECT_FALSE(is_classic_netcdf(cdf1, 3));
    EXPECT_THROW(read_classic_layout(hdf, 4, 4), Error);
}

TEST(NetcdfClassic, FixedVariablesDeclareTheirEnd)
{
    for (int version : {1, 2}) {
        uint64_t end = 0;
        const Header h = geotop_header(version, 3, 5, 7, end);
        const ClassicLayout l = layout_of(h, end);
        EXPECT_EQ(l.version, version);
        EXPECT_EQ(l.header_bytes, h.size());
        // 3 x 5 x 7 shorts, unpadded at the end of the file
        EXPECT_EQ(l.declared_bytes, end);
        EXPECT_EQ(end, h.size() + 12 + 20 + 28 + 210);
        EXPECT_EQ(l.last_variable, "lithok");
        EXPECT_NO_THROW(check_classic_length(l, end, "f.nc"));
        EXPECT_NO_THROW(check_classic_length(l, end + 100, "f.nc"));
    }
}

TEST(NetcdfClassic, Issue28TruncatedFileIsNamedWithBothLengths)
{
    uint64_t end = 0;
    const Header h = geotop_header(2, 30, 60, 100, end);
    const std::string m = error_of(h, end * 2 / 3);
    EXPECT_NE(m.find("file is truncated: header declares " + std::to_string(end) +
                     " bytes, file has " + std::to_string(end * 2 / 3)),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("f.nc"), std::string::npos) << m;
    EXPECT_NE(m.find("lithok"), std::string::npos) << m;
    EXPECT_EQ(error_of(h, end), "");
    EXPECT_NE(error_of(h, end - 1), "");
}

TEST(NetcdfClassic, HugeDeclarationWithLittleWritten)
{
    // 30000 x 30000 x 313 shorts declared: 563 GB, a 1 kB file
    uint64_t end = 0;
    const Header h = geotop_header(2, 30000, 30000, 313, end);
    const std::string m = error_of(h, 1024);
    EXPECT_NE(m.find("header declares " + std::to_string(end)), std::string::npos) << m;
    EXPECT_GT(end, 563000000000ull);
}

TEST(NetcdfClassic, Cdf5HasEightByteCountsAndNewTypes)
{
    auto make = [](uint64_t begin) {
        Header h(5);
        h.dims({{"x", 4}, {"z", 3}}).absent().u32(11).non_neg(1);
        return h.var("v", {0, 1}, 10 /* NC_INT64 */, 96, begin);
    };
    const uint64_t begin = make(0).size();
    const Header h = make(begin);
    EXPECT_EQ(layout_of(h, begin + 96).declared_bytes, begin + 96);
    EXPECT_EQ(error_of(h, begin + 96), "");
    EXPECT_NE(error_of(h, begin + 95), "");
    // NC_INT64 is no type of CDF-1
    Header h1(1);
    h1.dims({{"x", 4}}).absent().u32(11).non_neg(1).var("v", {0}, 10, 32, 200);
    EXPECT_NE(error_of(h1, 1000).find("type 10"), std::string::npos);
}

TEST(NetcdfClassic, RecordsInterleaveAndOneRecordVariableIsUnpadded)
{
    // time unlimited, 5 records; a(time, x=3) byte and b(time) short
    auto two = [](uint64_t begin) {
        Header h(1, 5);
        h.dims({{"time", 0}, {"x", 3}}).absent().u32(11).non_neg(2);
        return h.var("a", {0, 1}, 1, 4, begin).var("b", {0}, 3, 4, begin + 4);
    };
    const uint64_t begin = two(0).size();
    // records of 4 + 4 bytes; b of the last record ends 2 bytes in
    EXPECT_EQ(layout_of(two(begin), 1 << 20).declared_bytes, begin + 4 * 8 + 4 + 2);
    EXPECT_EQ(layout_of(two(begin), 1 << 20).last_variable, "b");
    EXPECT_NE(error_of(two(begin), begin + 37), "");
    EXPECT_EQ(error_of(two(begin), begin + 38), "");
    // one record variable: records of 3 bytes, no padding
    auto one = [](uint64_t begin) {
        Header h(1, 5);
        h.dims({{"time", 0}, {"x", 3}}).absent().u32(11).non_neg(1);
        return h.var("a", {0, 1}, 1, 4, begin);
    };
    const uint64_t b1 = one(0).size();
    EXPECT_EQ(layout_of(one(b1), 1 << 20).declared_bytes, b1 + 15);
}

TEST(NetcdfClassic, StreamingTakesTheRecordsTheFileHolds)
{
    auto make = [](uint64_t begin) {
        Header h(1, 0xFFFFFFFF);
        h.dims({{"time", 0}, {"x", 2}}).absent().u32(11).non_neg(1);
        return h.var("a", {0, 1}, 5, 8, begin);
    };
    const uint64_t begin = make(0).size();
    const ClassicLayout l = layout_of(make(begin), begin + 8 * 7 + 5);
    EXPECT_TRUE(l.streaming);
    EXPECT_EQ(l.numrecs, 7u);
    EXPECT_EQ(l.declared_bytes, begin + 56);
}

TEST(NetcdfClassic, ShortPrefixAsksForMore)
{
    uint64_t end = 0;
    const Header h = geotop_header(1, 3, 5, 7, end);
    // the first 20 bytes of a longer file: nothing decided yet
    EXPECT_FALSE(read_classic_layout(h.bytes().data(), 20, end).has_value());
    // the whole header of that file: decided
    EXPECT_TRUE(read_classic_layout(h.bytes().data(), h.size(), end).has_value());
    // a file that ends inside its header is truncated
    try {
        read_classic_layout(h.bytes().data(), 20, 20);
        FAIL() << "no error";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("truncated inside its header"), std::string::npos)
            << e.what();
    }
}

TEST(NetcdfClassic, HostileCountsAndLengthsFailWithoutAllocating)
{
    // 2^32 - 1 dimensions, attributes, variables announced in a tiny file
    for (uint32_t tag : {10u, 12u}) {
        Header h(1);
        if (tag == 12)
            h.absent();
        h.u32(tag).non_neg(0xFFFFFFFF).name("x").non_neg(1);
        EXPECT_NE(error_of(h, h.size()).find("truncated"), std::string::npos);
    }
    Header vars(5);
    vars.absent().absent().u32(11).non_neg(~0ull >> 1);
    EXPECT_NE(error_of(vars, vars.size()), "");
    // a name of 2^64 - 1 bytes, an attribute of 2^63 doubles
    Header name(5);
    name.u32(10).non_neg(1).non_neg(~0ull);
    EXPECT_NE(error_of(name, name.size()).find("more than 2^64"), std::string::npos);
    Header attr(5);
    attr.absent().u32(12).non_neg(1).name("a").u32(6).non_neg(1ull << 63);
    EXPECT_NE(error_of(attr, attr.size()).find("attribute values"), std::string::npos);
    // unknown tag, unknown type, dimension id out of range
    Header tag(1);
    tag.u32(99).non_neg(1);
    EXPECT_NE(error_of(tag, 1000).find("tag 99"), std::string::npos);
    Header type(1);
    type.dims({{"x", 2}}).absent().u32(11).non_neg(1).var("v", {0}, 0, 0, 100);
    EXPECT_NE(error_of(type, 1000).find("type 0"), std::string::npos);
    Header id(1);
    id.dims({{"x", 2}}).absent().u32(11).non_neg(1).var("v", {7}, 1, 4, 100);
    EXPECT_NE(error_of(id, 1000).find("dimension 7 of 1"), std::string::npos);
    // two record dimensions; the record dimension not first
    Header two(1);
    two.dims({{"t", 0}, {"u", 0}});
    EXPECT_NE(error_of(two, 1000).find("two record"), std::string::npos);
    Header late(1, 2);
    late.dims({{"t", 0}, {"x", 2}}).absent().u32(11).non_neg(1).var("v", {1, 0}, 1, 4, 100);
    EXPECT_NE(error_of(late, 1000).find("other than first"), std::string::npos);
}

TEST(NetcdfClassic, HostileSizesSaturateInsteadOfWrapping)
{
    // dimensions whose product wraps 64 bits: declared size saturates
    auto make = [](uint64_t begin) {
        Header h(5);
        h.dims({{"a", 1ull << 40}, {"b", 1ull << 40}}).absent().u32(11).non_neg(1);
        return h.var("v", {0, 1}, 6, 0, begin);
    };
    const uint64_t begin = make(0).size();
    const Header h = make(begin);
    const ClassicLayout l = layout_of(h, begin);
    EXPECT_EQ(l.declared_bytes, UINT64_MAX);
    EXPECT_NE(error_of(h, begin).find("more than 2^64"), std::string::npos);
    // data that begins inside the header
    Header inside(1);
    inside.dims({{"x", 2}}).absent().u32(11).non_neg(1).var("v", {0}, 1, 4, 8);
    EXPECT_NE(error_of(inside, 1000).find("inside the header"), std::string::npos);
    // records past 2^64 with a huge numrecs
    auto recs = [](uint64_t begin) {
        Header h(5, 1ull << 62);
        h.dims({{"t", 0}, {"x", 1ull << 20}}).absent().u32(11).non_neg(1);
        return h.var("v", {0, 1}, 6, 0, begin);
    };
    const uint64_t rb = recs(0).size();
    EXPECT_EQ(layout_of(recs(rb), rb).declared_bytes, UINT64_MAX);
}
