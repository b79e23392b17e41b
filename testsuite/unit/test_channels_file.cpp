/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Property channels (issue 29): the `channels` member round
 *            trip is bit-exact (integers, floats, NaN, fills), blocks are
 *            decoded only when a cell of theirs is asked for, and a
 *            damaged or mismatched file is refused by name
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/channels_file.hpp"
#include "format/format.hpp"
#include "format/mapped_file.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

using sbrt_test::Source;
using sbrt_test::source_value;
using sbrt_test::write_channels;

struct Fixture {
    Model model;
    Source source;
    std::vector<ChannelInfo> infos;
};

/// Random voxels (caves, air) with four channels: percentages with a fill,
/// negative integers, wide integers, and floats with NaN.
Fixture fixture(unsigned seed, int rows, int cols, int depths)
{
    Fixture fx;
    fx.model = sbrt_test::build_model(sbrt_test::random_voxels(seed, rows, cols, depths));
    const uint64_t voxels = fx.model.frame().voxels();
    std::mt19937 rng(seed);
    fx.source.assign(4, std::vector<float>(voxels));
    for (uint64_t i = 0; i < voxels; ++i) {
        const float smooth = float(i % 97);
        fx.source[0][i] = rng() % 7 == 0 ? -127.0f : float(rng() % 101);
        fx.source[1][i] = float(int(rng() % 300) - 200);
        fx.source[2][i] = float(int(rng() % 200000) - 100000) + smooth;
        fx.source[3][i] = rng() % 11 == 0 ? std::numeric_limits<float>::quiet_NaN()
                                          : std::ldexp(float(rng() % 100000), -7) - 3.3f;
    }
    ChannelInfo p;
    p.name = "kans_1";
    p.long_name = "kans op lithoklasse 1";
    p.unit = "%";
    p.has_fill = true;
    p.fill = -127;
    ChannelInfo n;
    n.name = "negative";
    ChannelInfo w;
    w.name = "wide";
    w.scale = 0.01;
    w.offset = 5;
    ChannelInfo r;
    r.name = "float";
    r.has_fill = true;
    r.fill = std::numeric_limits<float>::quiet_NaN();
    fx.infos = {p, n, w, r};
    return fx;
}

bool same_bits(float a, float b)
{
    return std::memcmp(&a, &b, 4) == 0;
}

} // namespace

TEST(ChannelsFile, RoundTripIsBitExactEverywhereInTheSpans)
{
    const std::string dir = sbrt_test::temp_dir("channels");
    for (int block : {1, 5, 64}) {
        const Fixture fx = fixture(3 + unsigned(block), 23, 31, 40);
        const std::string path = dir + "/channels" + std::to_string(block);
        write_channels(path, fx.model, fx.source, fx.infos, block);
        const PropertyChannels channels(std::make_shared<const MappedFile>(path), path,
                                        fx.model);
        ASSERT_EQ(channels.size(), 4u);
        const Frame &f = fx.model.frame();
        uint64_t compared = 0;
        for (uint64_t cell = 0; cell < f.cells(); ++cell) {
            const ColumnSpan span = channels.span(cell);
            EXPECT_EQ(span.lo, solid_span(fx.model, cell).lo);
            for (size_t ch = 0; ch < 4; ++ch)
                for (uint32_t z = 0; z < uint32_t(f.depths); ++z) {
                    float v = 0;
                    const bool inside = channels.value(ch, cell, z, v);
                    ASSERT_EQ(inside, span.holds(z));
                    if (!inside)
                        continue;
                    ASSERT_TRUE(same_bits(v, source_value(fx.source, f, ch, cell, z)))
                        << "block " << block << " channel " << ch << " cell " << cell
                        << " level " << z << ": " << v;
                    ++compared;
                }
        }
        EXPECT_GT(compared, f.voxels()); // most of the 4 x voxels lie in spans
    }
}

TEST(ChannelsFile, FiguresAndTypesDescribeTheValues)
{
    const std::string dir = sbrt_test::temp_dir("channels_figures");
    const Fixture fx = fixture(9, 12, 17, 30);
    const std::vector<ChannelInfo> written =
        write_channels(dir + "/c", fx.model, fx.source, fx.infos, 8);
    const PropertyChannels channels(std::make_shared<const MappedFile>(dir + "/c"),
                                    dir + "/c", fx.model);
    // a reference over the spans
    const Frame &f = fx.model.frame();
    uint64_t voxels = 0, valid = 0;
    double least = 1e9, most = -1e9;
    for (uint64_t cell = 0; cell < f.cells(); ++cell) {
        const ColumnSpan span = solid_span(fx.model, cell);
        for (uint32_t z = span.lo; z < span.hi; ++z) {
            ++voxels;
            const float v = source_value(fx.source, f, 0, cell, z);
            if (v != -127) {
                ++valid;
                least = std::min(least, double(v));
                most = std::max(most, double(v));
            }
        }
    }
    const ChannelInfo &p = channels.info(0);
    EXPECT_EQ(p.name, "kans_1");
    EXPECT_EQ(p.long_name, "kans op lithoklasse 1");
    EXPECT_EQ(p.unit, "%");
    EXPECT_EQ(p.voxels, voxels);
    EXPECT_EQ(p.valid, valid);
    EXPECT_EQ(p.min, least);
    EXPECT_EQ(p.max, most);
    EXPECT_EQ(p.type(), ChannelType::int8); // 0..100 and the fill -127
    EXPECT_EQ(channels.info(1).type(), ChannelType::int16);
    EXPECT_EQ(channels.info(2).type(), ChannelType::float32); // beyond 16 bits
    EXPECT_EQ(channels.info(2).scale, 0.01);
    EXPECT_EQ(channels.info(2).offset, 5);
    EXPECT_EQ(channels.info(3).type(), ChannelType::float32);
    EXPECT_TRUE(std::isnan(channels.info(3).fill));
    EXPECT_EQ(channels.info(3).valid + 0, written[3].valid);
    EXPECT_GT(p.bytes, 0u);
    EXPECT_EQ(channels.find("wide"), 2);
    EXPECT_EQ(channels.find("nothing"), -1);
}

TEST(ChannelsFile, BlocksAreDecodedOnlyWhereAsked)
{
    const std::string dir = sbrt_test::temp_dir("channels_lazy");
    const Fixture fx = fixture(4, 40, 40, 20);
    write_channels(dir + "/c", fx.model, fx.source, fx.infos, 8); // 25 blocks
    const PropertyChannels channels(std::make_shared<const MappedFile>(dir + "/c"),
                                    dir + "/c", fx.model);
    EXPECT_EQ(channels.block_count(), 100u);
    EXPECT_EQ(channels.blocks_decoded(), 0u);
    uint64_t cell = 0;
    while (channels.span(cell).size() == 0)
        ++cell;
    float v;
    ASSERT_TRUE(channels.value(1, cell, channels.span(cell).lo, v));
    ASSERT_TRUE(channels.value(1, cell, channels.span(cell).hi - 1, v));
    EXPECT_EQ(channels.blocks_decoded(), 1u);
}

TEST(ChannelsFile, DamageAndMismatchAreRefusedByName)
{
    const std::string dir = sbrt_test::temp_dir("channels_bad");
    const Fixture fx = fixture(5, 16, 16, 20);
    const std::string path = dir + "/c";
    write_channels(path, fx.model, fx.source, fx.infos, 8);
    std::vector<uint8_t> bytes = read_file_bytes(path);
    auto open_bytes = [&](const std::vector<uint8_t> &b, const Model &m) {
        std::ofstream(dir + "/d", std::ios::binary)
            .write(reinterpret_cast<const char *>(b.data()), std::streamsize(b.size()));
        const PropertyChannels c(std::make_shared<const MappedFile>(dir + "/d"), dir + "/d", m);
        // decode every block
        for (size_t ch = 0; ch < c.size(); ++ch)
            for (uint64_t cell = 0; cell < m.frame().cells(); ++cell)
                c.column(ch, cell);
    };
    EXPECT_NO_THROW(open_bytes(bytes, fx.model));
    // every single flipped byte: refused (header, blocks, directory) or
    // harmless; never a crash (ASan runs this too)
    size_t refused = 0;
    for (size_t at = 0; at < bytes.size(); at += 7) {
        std::vector<uint8_t> bad = bytes;
        bad[at] ^= 0x5a;
        try {
            open_bytes(bad, fx.model);
        }
        catch (const Error &e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find(dir + "/d"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(refused, (bytes.size() + 6) / 7);
    // truncated
    EXPECT_THROW(open_bytes(std::vector<uint8_t>(bytes.begin(), bytes.end() - 9), fx.model),
                 Error);
    // another model: other grid, or the same grid with other spans
    EXPECT_THROW(open_bytes(bytes, fixture(5, 16, 17, 20).model), Error);
    try {
        open_bytes(bytes, fixture(6, 16, 16, 20).model);
        ADD_FAILURE() << "channels of another model's spans read";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("do not match the stacks"), std::string::npos)
            << e.what();
    }
}

TEST(ChannelsFile, TravelWithTheSbrtAndMarkTheStacks)
{
    const std::string dir = sbrt_test::temp_dir("channels_sbrt");
    const Fixture fx = fixture(7, 20, 30, 25);
    write_channels(dir + "/staged", fx.model, fx.source, fx.infos, 64);
    write_sbrt(dir + "/m", fx.model, "hist\n", {}, dir + "/staged");
    const Model back = read_sbrt(dir + "/m");
    const auto channels = read_channels(dir + "/m", back);
    ASSERT_TRUE(channels);
    EXPECT_EQ(channels->size(), 4u);
    float v;
    for (uint64_t cell = 0; cell < back.frame().cells(); ++cell)
        if (channels->span(cell).size()) {
            ASSERT_TRUE(channels->value(2, cell, channels->span(cell).lo, v));
            EXPECT_EQ(v, source_value(fx.source, back.frame(), 2, cell,
                                      channels->span(cell).lo));
        }
    // the stacks say so (optional feature bit 0), the header lists them
    const std::vector<uint8_t> stacks = read_file_bytes(dir + "/m/stacks");
    EXPECT_EQ(stacks[20] & V2_OPTIONAL_CHANNELS, V2_OPTIONAL_CHANNELS);
    const std::vector<uint8_t> header = read_file_bytes(dir + "/m/header");
    EXPECT_NE(std::string(header.begin(), header.end()).find("channels:    4"),
              std::string::npos);
    // an SBRT without channels has none and no feature bit
    write_sbrt(dir + "/plain", fx.model, "hist\n");
    EXPECT_FALSE(read_channels(dir + "/plain", read_sbrt(dir + "/plain")));
    EXPECT_EQ(read_file_bytes(dir + "/plain/stacks")[20] & V2_OPTIONAL_CHANNELS, 0);
    // channels in other blocks than the stacks are refused
    write_channels(dir + "/other", fx.model, fx.source, fx.infos, 16);
    EXPECT_THROW(write_sbrt(dir + "/m2", fx.model, "hist\n", {}, dir + "/other"), Error);
    remove_tree(dir);
}

TEST(ChannelsFile, HorizonModelsHaveNoSpans)
{
    Frame f;
    f.rows = f.cols = 1;
    f.depths = 10;
    Intervals iv;
    iv.push_back({1, 2.5f});
    Material one;
    one.id = 1;
    const Model m(f, {Material{}, one}, std::vector<uint32_t>{0, 1},
                  IntervalArray(std::move(iv)));
    EXPECT_FALSE(has_voxel_tops(m));
    EXPECT_THROW(solid_span(m, 0), Error);
}

TEST(PendingValues, HoldEveryValueBitExactlyWhileWideningAsValuesNeed)
{
    PendingValues pending;
    std::vector<float> all;
    auto add = [&](std::vector<float> values) {
        pending.append(values.data(), values.size());
        all.insert(all.end(), values.begin(), values.end());
    };
    add({0, 100, -127, 5});            // bytes
    add({300, -2000, 7});              // int16: the bytes before widened
    add({-0.0f, 2.5f, std::numeric_limits<float>::quiet_NaN(), 1e9f}); // floats
    add({3, -127});
    std::vector<float> got;
    pending.floats(got);
    ASSERT_EQ(got.size(), all.size());
    EXPECT_EQ(pending.size(), all.size());
    for (size_t i = 0; i < all.size(); ++i)
        EXPECT_EQ(std::memcmp(&got[i], &all[i], 4), 0) << i;
    pending.clear();
    add({});
    pending.floats(got);
    EXPECT_TRUE(got.empty());
    // narrow again after clear: -0 alone still comes back as -0
    const float minus_zero = -0.0f;
    pending.append(&minus_zero, 1);
    pending.floats(got);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_TRUE(std::signbit(got[0]));
}
