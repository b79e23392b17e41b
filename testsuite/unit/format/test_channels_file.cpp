/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Property channels (issue 29): the `channels` member round
 *            trip is bit-exact (integers, floats, NaN, fills), blocks are
 *            decoded only when a cell of theirs is asked for, and a
 *            damaged or mismatched file is refused by name; each channel's
 *            kind (issue 51) is stored, derived from the unit in files of
 *            1.0, set again with the blocks untouched, and set on import
 *            by a survey preset's channel lines
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "format/atomic_dir.hpp"
#include "format/byte_io.hpp"
#include "format/channels_file.hpp"
#include "format/channels_rewrite.hpp"
#include "format/format.hpp"
#include "format/mapped_file.hpp"
#include "model/legend_rules.hpp"
#include "model/survey_presets.hpp"
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

// ------------------------------------------------------- kinds (issue 51)

namespace {

/// `bytes` as channels file version 1.`minor` with its directory's last
/// `drop` bytes removed and checksums made right again (a file as another
/// writer would have written it).
std::vector<uint8_t> resealed(std::vector<uint8_t> bytes, uint16_t minor, size_t drop)
{
    bytes.resize(bytes.size() - drop);
    const uint64_t dir_at = load_le(&bytes[32], 8);
    store_le(&bytes[10], minor, 2);
    store_le(&bytes[40], bytes.size(), 8);
    store_le(&bytes[48], crc32_of(bytes.data() + dir_at, bytes.size() - dir_at), 4);
    store_le(&bytes[60], crc32_of(bytes.data(), 60), 4);
    return bytes;
}

PropertyChannels open_channels(const std::string &path, const std::vector<uint8_t> &bytes,
                               const Model &model)
{
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
    return PropertyChannels(std::make_shared<const MappedFile>(path), path, model);
}

} // namespace

TEST(ChannelKinds, AreStoredOrTakenFromTheUnit)
{
    const std::string dir = sbrt_test::temp_dir("channel_kinds");
    Fixture fx = fixture(11, 9, 13, 20);
    fx.infos[1].kind = ChannelKind::uncertainty;
    fx.infos[2].kind = ChannelKind::probability; // set: stored whatever the unit
    fx.infos[3].unit = "m";                      // unset, not "%": other
    write_channels(dir + "/c", fx.model, fx.source, fx.infos, 8);
    const PropertyChannels channels(std::make_shared<const MappedFile>(dir + "/c"),
                                    dir + "/c", fx.model);
    EXPECT_EQ(channels.info(0).kind, ChannelKind::probability); // unset, unit "%"
    EXPECT_EQ(channels.info(1).kind, ChannelKind::uncertainty);
    EXPECT_EQ(channels.info(2).kind, ChannelKind::probability);
    EXPECT_EQ(channels.info(3).kind, ChannelKind::other);
    // names both ways
    for (const char *name : {"probability", "percentage", "uncertainty", "other"}) {
        ChannelKind k = ChannelKind::unset;
        ASSERT_TRUE(parse_channel_kind(name, k)) << name;
        EXPECT_STREQ(channel_kind_name(k), name);
    }
    ChannelKind k = ChannelKind::unset;
    EXPECT_FALSE(parse_channel_kind("", k));
    EXPECT_FALSE(parse_channel_kind("Probability", k));
    remove_tree(dir);
}

TEST(ChannelKinds, FilesOfVersionOneZeroAreReadWithKindsFromTheirUnits)
{
    const std::string dir = sbrt_test::temp_dir("channel_kinds_v10");
    Fixture fx = fixture(12, 10, 11, 20);
    fx.infos[0].kind = ChannelKind::percentage; // lost: 1.0 has no kinds
    fx.infos[1].unit = "%";
    write_channels(dir + "/c", fx.model, fx.source, fx.infos, 8);
    const std::vector<uint8_t> bytes = read_file_bytes(dir + "/c");
    EXPECT_EQ(load_le(&bytes[10], 2), 1u); // written as 1.1
    // 1.0: the same without the kinds after the last channel
    const PropertyChannels old =
        open_channels(dir + "/v10", resealed(bytes, 0, fx.infos.size()), fx.model);
    EXPECT_EQ(old.info(0).kind, ChannelKind::probability); // unit "%"
    EXPECT_EQ(old.info(1).kind, ChannelKind::probability);
    EXPECT_EQ(old.info(2).kind, ChannelKind::other);
    float a = 0, b = 0;
    const PropertyChannels now(std::make_shared<const MappedFile>(dir + "/c"), dir + "/c",
                               fx.model);
    for (uint64_t cell = 0; cell < fx.model.frame().cells(); ++cell)
        if (now.span(cell).size()) {
            ASSERT_TRUE(old.value(2, cell, now.span(cell).lo, a));
            ASSERT_TRUE(now.value(2, cell, now.span(cell).lo, b));
            EXPECT_EQ(a, b);
        }
    // a later 1.x with more after the kinds: read, the rest ignored
    std::vector<uint8_t> later = bytes;
    later.insert(later.end(), {7, 7, 7});
    EXPECT_EQ(open_channels(dir + "/v12", resealed(later, 2, 0), fx.model).info(0).kind,
              ChannelKind::percentage);
    remove_tree(dir);
}

TEST(ChannelKinds, AnUnknownOrMissingKindIsRefusedByName)
{
    const std::string dir = sbrt_test::temp_dir("channel_kinds_bad");
    const Fixture fx = fixture(13, 8, 9, 16);
    write_channels(dir + "/c", fx.model, fx.source, fx.infos, 8);
    const std::vector<uint8_t> bytes = read_file_bytes(dir + "/c");
    for (const uint8_t bad : {uint8_t(0), uint8_t(LAST_CHANNEL_KIND + 1), uint8_t(255)}) {
        std::vector<uint8_t> b = bytes;
        b[b.size() - 2] = bad; // the third channel's (wide)
        try {
            open_channels(dir + "/d", resealed(b, 1, 0), fx.model);
            ADD_FAILURE() << "kind " << int(bad) << " read";
        }
        catch (const Error &e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(dir + "/d"), std::string::npos) << what;
            EXPECT_NE(what.find("wide has kind " + std::to_string(bad)), std::string::npos)
                << what;
        }
    }
    // 1.1 cut before its kinds: the directory ends too soon
    EXPECT_THROW(open_channels(dir + "/d", resealed(bytes, 1, 2), fx.model), Error);
    remove_tree(dir);
}

TEST(ChannelKinds, ARewriteChangesLegendsNotValues)
{
    const std::string dir = sbrt_test::temp_dir("channel_kinds_rewrite");
    const Fixture fx = fixture(14, 17, 19, 24);
    write_channels(dir + "/staged", fx.model, fx.source, fx.infos, 64);
    write_sbrt(dir + "/m", fx.model, "first\n", {}, dir + "/staged");
    const Model model = read_sbrt(dir + "/m");
    const auto before = read_channels(dir + "/m", model);
    const std::vector<uint8_t> stacks = read_file_bytes(dir + "/m/stacks");
    std::vector<ChannelInfo> infos = before->infos();
    infos[1].unit = "%";
    infos[1].kind = ChannelKind::probability;
    infos[3].kind = ChannelKind::uncertainty;
    infos[3].long_name = "onzekerheid";
    rewrite_channels(dir + "/m", *before, infos, "second\n");
    const auto after = read_channels(dir + "/m", read_sbrt(dir + "/m"));
    ASSERT_TRUE(after);
    EXPECT_EQ(after->info(1).unit, "%");
    EXPECT_EQ(after->info(1).kind, ChannelKind::probability);
    EXPECT_EQ(after->info(3).kind, ChannelKind::uncertainty);
    EXPECT_EQ(after->info(3).long_name, "onzekerheid");
    EXPECT_EQ(after->info(0).kind, ChannelKind::probability);
    EXPECT_EQ(after->info(2).kind, ChannelKind::other);
    for (size_t ch = 0; ch < 4; ++ch) {
        EXPECT_EQ(after->info(ch).valid, before->info(ch).valid);
        EXPECT_EQ(after->info(ch).max, before->info(ch).max);
        for (uint64_t cell = 0; cell < model.frame().cells(); ++cell) {
            const ColumnSpan span = after->span(cell);
            for (uint32_t z = span.lo; z < span.hi; ++z) {
                float a = 0, b = 0;
                ASSERT_TRUE(before->value(ch, cell, z, a));
                ASSERT_TRUE(after->value(ch, cell, z, b));
                ASSERT_TRUE(same_bits(a, b)) << ch << " " << cell << " " << z;
            }
        }
    }
    const std::vector<uint8_t> hist = read_file_bytes(dir + "/m/hist");
    EXPECT_EQ(std::string(hist.begin(), hist.end()), "first\nsecond\n");
    EXPECT_EQ(read_file_bytes(dir + "/m/stacks"), stacks);
    // another count or another name: refused, the SBRT as it was
    std::vector<ChannelInfo> fewer(infos.begin(), infos.end() - 1);
    EXPECT_THROW(rewrite_channels(dir + "/m", *after, fewer, "x\n"), Error);
    std::vector<ChannelInfo> renamed = infos;
    renamed[2].name = "other";
    EXPECT_THROW(rewrite_channels(dir + "/m", *after, renamed, "x\n"), Error);
    EXPECT_EQ(read_channels(dir + "/m", read_sbrt(dir + "/m"))->info(3).long_name,
              "onzekerheid");
    remove_tree(dir);
}

TEST(ChannelKinds, PresetChannelLinesSetKindsWhereTheFileGaveNoUnit)
{
    std::istringstream in("name: t\nreference: r\n"
                          "channel: kans_* probability\n"
                          "channel: onz_* uncertainty\n"
                          "channel: p?   percentage   %\n"
                          "1 1:2:3 one\n");
    const SurveyPreset preset = parse_preset(in, "t.rules");
    ASSERT_EQ(preset.channels.size(), 3u);
    EXPECT_EQ(preset.channels[0].unit, "%"); // a probability is in %
    EXPECT_EQ(preset.channels[1].unit, "");
    std::vector<ChannelInfo> infos(6);
    const char *names[6] = {"kans_5", "kans_6", "onz_lk", "p1", "other", "kans_7"};
    for (size_t i = 0; i < 6; ++i)
        infos[i].name = names[i];
    infos[1].unit = "1"; // the file's own unit, another than the line's
    infos[4].unit = "%";
    infos[5].unit = "%";
    EXPECT_EQ(apply_channel_rules(preset, infos), 4u);
    EXPECT_EQ(infos[0].unit, "%");
    EXPECT_EQ(infos[0].kind, ChannelKind::probability);
    EXPECT_EQ(infos[1].unit, "1");
    EXPECT_EQ(infos[1].known_kind(), ChannelKind::other);
    EXPECT_EQ(infos[2].kind, ChannelKind::uncertainty);
    EXPECT_EQ(infos[2].unit, "");
    EXPECT_EQ(infos[3].kind, ChannelKind::percentage);
    EXPECT_EQ(infos[4].kind, ChannelKind::unset);
    EXPECT_EQ(infos[5].kind, ChannelKind::probability);
    // GeoTOP's presets say what kans_* and onz_* are
    for (const char *name : {"geotop_lithoclass", "geotop_strat"}) {
        std::vector<ChannelInfo> geotop(2);
        geotop[0].name = "kans_5";
        geotop[1].name = "onz_ls";
        apply_channel_rules(find_preset(name), geotop);
        EXPECT_EQ(geotop[0].kind, ChannelKind::probability) << name;
        EXPECT_EQ(geotop[0].unit, "%") << name;
        EXPECT_EQ(geotop[1].kind, ChannelKind::uncertainty) << name;
    }
    // bad lines: named
    for (const char *bad : {"channel: kans_*\n", "channel: kans_* likely\n",
                            "channel: kans_* probability 1\n",
                            "channel: a b c d\n"}) {
        std::istringstream b(std::string("name: t\nreference: r\n") + bad + "1 1:2:3 x\n");
        try {
            parse_preset(b, "t.rules");
            ADD_FAILURE() << bad;
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find("t.rules line 3"), std::string::npos)
                << e.what();
        }
    }
}
