/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Rendering by property (issue 29): the value the CPU path
 *            shows at a hit equals the source value of the first solid
 *            voxel an independent voxel walk finds, for random rays, with
 *            strata hidden and summed channels; the colour is the ramp's,
 *            lit as a class colour would be
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "format/mapped_file.hpp"
#include "builders/voxel_selection.hpp"
#include "scene/hidden_materials.hpp"
#include "shading/property_paint.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

constexpr float FILL = -127;

struct PropertyFixture {
    sbrt_test::Voxels voxels;
    Model model;
    sbrt_test::Source source;
    std::shared_ptr<const PropertyChannels> channels;
};

/// Unit cells (map frame = voxel frame), two channels: a percentage with
/// fills, and a second one to add to it.
PropertyFixture fixture(unsigned seed, const std::string &dir)
{
    PropertyFixture fx;
    fx.voxels = sbrt_test::random_voxels(seed, 9 + seed % 5, 7 + seed % 4, 12 + seed % 9, 6);
    Frame &f = fx.voxels.frame;
    f.west = 0;
    f.east = f.cols;
    f.south = 0;
    f.north = f.rows;
    f.bottom = 0;
    f.top = f.depths;
    fx.model = sbrt_test::build_model(fx.voxels);
    std::mt19937 rng(seed);
    fx.source.assign(2, std::vector<float>(f.voxels()));
    for (size_t i = 0; i < f.voxels(); ++i) {
        fx.source[0][i] = rng() % 13 == 0 ? FILL : float(rng() % 101);
        fx.source[1][i] = float(rng() % 50);
    }
    ChannelInfo a, b;
    a.name = "kans_5";
    a.has_fill = true;
    a.fill = FILL;
    b.name = "kans_6";
    b.scale = 2; // meant: stored * 2
    const std::string path = dir + "/channels" + std::to_string(seed);
    sbrt_test::write_channels(path, fx.model, fx.source, {a, b}, 4);
    fx.channels = std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(path), path, fx.model);
    return fx;
}

ColorRamp grey_ramp() { return ColorRamp::through({{0, 0, 0}, {250, 250, 250}}, 0, 250); }

/// Source value of the voxel (column x, row from the south y, level z).
float at(const PropertyFixture &fx, size_t channel, int x, int y, int z)
{
    const Frame &f = fx.voxels.frame;
    const size_t cell = size_t(f.rows - 1 - y) * size_t(f.cols) + size_t(x);
    return fx.source[channel][size_t(z) * f.cells() + cell];
}

} // namespace

TEST(PropertyPaint, ValueAtHitIsTheFirstSolidVoxelsValue)
{
    const std::string dir = sbrt_test::temp_dir("property_paint");
    int rays = 0, agree = 0, valued = 0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const PropertyFixture fx = fixture(seed, dir);
        const Tracer tracer(fx.model, 1.0);
        const PropertyPaint single(fx.model, fx.channels, {0}, grey_ramp());
        const PropertyPaint sum(fx.model, fx.channels, {0, 1}, grey_ramp());
        PropertyPaint kept(fx.model, fx.channels, {0, 1}, grey_ramp()); // sums per block
        kept.keep_block_sums();
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        const Frame &f = fx.voxels.frame;
        for (int k = 0; k < 2000; ++k) {
            const glm::dvec3 target(f.cols * (0.5 + 0.5 * u(rng)), f.rows * (0.5 + 0.5 * u(rng)),
                                    f.depths * (0.5 + 0.5 * u(rng)));
            const glm::dvec3 dir_ = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
            const glm::dvec3 origin = target - dir_ * 60.0;
            const Hit hit = tracer.trace({origin, dir_});
            const sbrt_test::VoxelHit want = sbrt_test::march(fx.voxels, origin, dir_);
            if (!want.hit)
                continue;
            ++rays;
            const float a = at(fx, 0, want.x, want.y, want.z);
            const float b = at(fx, 1, want.x, want.y, want.z);
            double got_single = NAN, got_sum = NAN;
            const bool has_single = single.value(hit, got_single);
            const bool has_sum = sum.value(hit, got_sum);
            double got_kept = NAN;
            EXPECT_EQ(kept.value(hit, got_kept), has_sum);
            if (has_sum) {
                EXPECT_EQ(got_kept, got_sum);
            }
            const bool same = a == FILL ? !has_single && !has_sum
                                        : has_single && got_single == a && has_sum &&
                                              got_sum == a + 2.0 * b;
            agree += same;
            valued += a != FILL;
            // the colour: the ramp's at the value (the integer sum's colour
            // table gives it), the no-value grey without one
            if (has_sum)
                EXPECT_EQ(sum.color(hit), sum.ramp().at(got_sum)) << got_sum;
            else
                EXPECT_EQ(sum.color(hit), glm::dvec3(190));
        }
    }
    EXPECT_GT(valued, rays / 2);
    // disagreement only where a ray passes exactly through an edge
    EXPECT_GE(agree, rays - rays / 1000) << agree << " of " << rays;
}

TEST(PropertyPaint, IntegerSumsColourFromATableAndOthersFromTheRamp)
{
    const std::string dir = sbrt_test::temp_dir("property_table");
    const PropertyFixture fx = fixture(3, dir);
    // a ramp with a step inside an integer's reach: a table off by one or
    // taking a fraction for the value would show
    const ColorRamp ramp({{{0, {0, 0, 0}}, {100, {250, 0, 0}}},
                          {{100.5, {0, 250, 0}}, {300, {0, 0, 250}}}});
    const PropertyPaint sum(fx.model, fx.channels, {0, 1}, ramp);
    const Tracer tracer(fx.model, 1.0);
    const Frame &f = fx.voxels.frame;
    int checked = 0;
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            const Hit hit = tracer.trace({{col + 0.5, f.rows - row - 0.5, f.depths + 5.0},
                                          {0, 0, -1}});
            double v;
            if (!sum.value(hit, v))
                continue;
            EXPECT_EQ(sum.color(hit), ramp.at(v)) << v;
            ++checked;
        }
    EXPECT_GT(checked, f.rows * f.cols / 3);
}

TEST(PropertyPaint, HiddenStrataShowTheValuesBehindThem)
{
    const std::string dir = sbrt_test::temp_dir("property_hidden");
    int rays = 0, agree = 0;
    for (unsigned seed = 3; seed <= 6; ++seed) {
        PropertyFixture fx = fixture(seed, dir);
        // material 1 and 2 hidden: the tracer sees the prepared model, the
        // channels stay with the model as read
        const Model prepared = hide_materials(fx.model, {1, 2});
        const Tracer tracer(prepared, 1.0);
        const PropertyPaint paint(fx.model, fx.channels, {0}, grey_ramp());
        sbrt_test::Voxels shown = fx.voxels;
        const int32_t hidden_a = fx.model.materials()[1].id, hidden_b = fx.model.materials()[2].id;
        for (int32_t &id : shown.classes)
            if (id == hidden_a || id == hidden_b)
                id = NULL_CLASS;
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        const Frame &f = fx.voxels.frame;
        for (int k = 0; k < 1500; ++k) {
            const glm::dvec3 target(f.cols * (0.5 + 0.5 * u(rng)), f.rows * (0.5 + 0.5 * u(rng)),
                                    f.depths * (0.5 + 0.5 * u(rng)));
            const glm::dvec3 d = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
            const Hit hit = tracer.trace({target - d * 60.0, d});
            const sbrt_test::VoxelHit want = sbrt_test::march(shown, target - d * 60.0, d);
            if (!want.hit)
                continue;
            ++rays;
            const float a = at(fx, 0, want.x, want.y, want.z);
            double got = NAN;
            const bool has = paint.value(hit, got);
            agree += a == FILL ? !has : has && got == a;
        }
    }
    EXPECT_GT(rays, 1000);
    EXPECT_GE(agree, rays - rays / 1000) << agree << " of " << rays;
}

TEST(PropertyPaint, TopViewColoursAreTheRampsLit)
{
    const std::string dir = sbrt_test::temp_dir("property_top");
    const PropertyFixture fx = fixture(5, dir);
    const Tracer tracer(fx.model, 1.0);
    const PropertyPaint paint(fx.model, fx.channels, {0}, grey_ramp());
    Shading shading;
    shading.property = &paint;
    const Frame &f = fx.voxels.frame;
    const Camera camera = sbrt_test::top_camera(f, f.top + 10);
    const Image image = shade(tracer, camera, trace_image(tracer, camera, 2), shading, 2);
    ASSERT_EQ(image.value.size(), size_t(f.rows) * size_t(f.cols));
    const double light = shading.ambient + (1 - shading.ambient) *
                                               glm::dot(shading.light, glm::dvec3(0, 0, 1));
    int checked = 0;
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            const size_t i = size_t(row) * size_t(f.cols) + size_t(col);
            // the topmost solid voxel of the column
            int top = -1;
            for (int z = f.depths - 1; z >= 0 && top < 0; --z)
                if (fx.voxels.classes[(size_t(z) * f.rows + row) * f.cols + col] != NULL_CLASS)
                    top = z;
            if (top < 0) {
                EXPECT_TRUE(std::isnan(image.value[i]));
                continue;
            }
            const float v = at(fx, 0, col, f.rows - 1 - row, top);
            if (v == FILL) {
                EXPECT_TRUE(std::isnan(image.value[i]));
                EXPECT_EQ(image.rgb[i * 3], uint8_t(std::lround(190 * light)));
                continue;
            }
            EXPECT_EQ(image.value[i], v);
            EXPECT_EQ(image.rgb[i * 3], uint8_t(std::lround(v * light))) << v;
            ++checked;
        }
    EXPECT_GT(checked, f.rows * f.cols / 2);
}

TEST(ColorRamp, InterpolatesBetweenRulesAndClampsOutside)
{
    const ColorRamp ramp({{{0, {0, 0, 0}}, {10, {100, 200, 50}}},
                          {{10, {0, 0, 255}}, {20, {255, 255, 255}}}});
    EXPECT_EQ(ramp.rgb_at(-5), (std::array<uint8_t, 3>{0, 0, 0}));
    EXPECT_EQ(ramp.rgb_at(5), (std::array<uint8_t, 3>{50, 100, 25}));
    EXPECT_EQ(ramp.rgb_at(15), (std::array<uint8_t, 3>{128, 128, 255}));
    EXPECT_EQ(ramp.rgb_at(25), (std::array<uint8_t, 3>{255, 255, 255}));
    EXPECT_EQ(ramp.low(), 0);
    EXPECT_EQ(ramp.high(), 20);
    EXPECT_THROW(ColorRamp(std::vector<ColorRamp::Rule>{}), Error);
}

/// The colour GRASS's rules give `value` read rule by rule (in the ramp's
/// order: by start, ties as given): the last rule that holds it, else the
/// end of the nearest rule below (the first rule's start below them all).
glm::dvec3 reference_color(const std::vector<ColorRamp::Rule> &rules, double value)
{
    auto color = [](const ColorRamp::Stop &s) { return glm::dvec3(s.rgb[0], s.rgb[1], s.rgb[2]); };
    const ColorRamp::Rule *first = &rules.front();
    for (const ColorRamp::Rule &r : rules)
        if (r.low.value < first->low.value)
            first = &r;
    if (!(value > first->low.value))
        return color(first->low);
    const ColorRamp::Rule *holding = nullptr, *below = first;
    for (const ColorRamp::Rule &r : rules) {
        if (value >= r.low.value && value <= r.high.value &&
            (!holding || r.low.value >= holding->low.value))
            holding = &r;
        if (r.high.value <= value && r.high.value >= below->high.value)
            below = &r;
    }
    if (!holding)
        return color(below->high);
    const double span = holding->high.value - holding->low.value;
    const double f = span > 0 ? (value - holding->low.value) / span : 0;
    return color(holding->low) + f * (color(holding->high) - color(holding->low));
}

TEST(ColorRamp, BisectionGivesEachValueItsRulesColour)
{
    // rules in order as GRASS's tables are (touching), with gaps between
    // some, a zero-width rule, and given out of order: at() bisects them
    std::mt19937 random(29);
    std::uniform_int_distribution<int> byte(0, 255);
    auto stop = [&](double v) {
        return ColorRamp::Stop{v, {uint8_t(byte(random)), uint8_t(byte(random)),
                                   uint8_t(byte(random))}};
    };
    std::vector<ColorRamp::Rule> rules;
    double at = -3;
    for (int i = 0; i < 200; ++i) {
        const bool gap = i % 11 == 3 || i % 37 == 5; // a gap now and then
        const double width = i % 37 == 5 ? 0 : 0.25 + (i % 7) * 0.5; // one of no width
        rules.push_back({stop(at), stop(at + width)});
        at += width + (gap ? 1.5 : 0);
    }
    // the same rules overlapping where one is made longer: read one by one
    std::vector<ColorRamp::Rule> overlapping = rules;
    overlapping[50].high = stop(overlapping[53].low.value + 0.1);
    for (const auto &[given, disjoint] : {std::pair{rules, true}, std::pair{overlapping, false}}) {
        std::vector<ColorRamp::Rule> shuffled = given;
        std::shuffle(shuffled.begin(), shuffled.end(), random);
        const ColorRamp ramp(shuffled);
        ASSERT_EQ(ramp.disjoint(), disjoint);
        std::uniform_real_distribution<double> anywhere(-10, at + 10);
        std::vector<double> values = {-3, at, at + 1, NAN};
        for (const ColorRamp::Rule &r : given)
            values.insert(values.end(), {r.low.value, r.high.value, r.high.value + 0.75});
        for (int i = 0; i < 20000; ++i)
            values.push_back(anywhere(random));
        for (const double v : values) {
            const glm::dvec3 got = ramp.at(v), want = reference_color(ramp.rules(), v);
            ASSERT_EQ(got, want) << "value " << v << (disjoint ? "" : " (overlapping)");
        }
    }
}

TEST(VoxelSelection, KeepsExactlyTheVoxelsMeetingTheCondition)
{
    const std::string dir = sbrt_test::temp_dir("selection");
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const PropertyFixture fx = fixture(seed, dir);
        // >= over a sum; < where a fill (-127) would meet it
        const bool at_least = seed % 2 == 0;
        const Selection s = parse_selection(at_least ? "kans_5 + kans_6 >= 90"
                                                     : "kans_5+kans_6<60",
                                            *fx.channels);
        ASSERT_EQ(s.channels.size(), 2u);
        const Model selected = select_voxels(fx.model, *fx.channels, s, 2);
        selected.validate();
        const Frame &f = fx.voxels.frame;
        uint64_t kept = 0, voxels = 0;
        for (int row = 0; row < f.rows; ++row)
            for (int col = 0; col < f.cols; ++col) {
                const uint64_t cell = selected.cell_index(row, col);
                const std::vector<Interval> stack = selected.stack_intervals(cell);
                size_t i = 0;
                for (int z = 0; z < f.depths; ++z) {
                    while (i < stack.size() && stack[i].top <= float(z))
                        ++i;
                    const int32_t got =
                        i < stack.size() ? selected.materials()[stack[i].material].id : NULL_CLASS;
                    const size_t v = (size_t(z) * f.rows + row) * f.cols + col;
                    const int32_t id = fx.voxels.classes[v];
                    const float a = fx.source[0][v], b = fx.source[1][v];
                    const double sum = a + 2.0 * b;
                    const bool meets =
                        id != NULL_CLASS && a != FILL && (at_least ? sum >= 90 : sum < 60);
                    ASSERT_EQ(got, meets ? id : NULL_CLASS)
                        << "seed " << seed << " row " << row << " col " << col << " z " << z;
                    kept += meets;
                    voxels += id != NULL_CLASS;
                }
            }
        EXPECT_GT(kept, 0u);
        EXPECT_LT(kept, voxels);
    }
}

TEST(VoxelSelection, BadConditionsAreRefusedByName)
{
    const std::string dir = sbrt_test::temp_dir("selection_bad");
    const PropertyFixture fx = fixture(2, dir);
    auto message = [&](const std::string &text) {
        try {
            parse_selection(text, *fx.channels);
        }
        catch (const Error &e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("kans_5").find("no condition"), std::string::npos);
    EXPECT_NE(message(">= 60").find("names no channel"), std::string::npos);
    EXPECT_NE(message("kans_9 >= 60").find("no property channel 'kans_9'"), std::string::npos);
    EXPECT_NE(message("kans_9 >= 60").find("kans_5, kans_6"), std::string::npos);
    EXPECT_NE(message("kans_5 >= sixty").find("not a number"), std::string::npos);
    EXPECT_EQ(message("kans_5<7"), "accepted");
    EXPECT_EQ(parse_selection("kans_5<7", *fx.channels).comparison, Comparison::less);
    EXPECT_EQ(parse_selection("kans_6!=7", *fx.channels).comparison, Comparison::not_equal);
}

TEST(UncertaintyFade, TopViewGreysByTheVoxelsUncertainty)
{
    const std::string dir = sbrt_test::temp_dir("fade");
    const PropertyFixture fx = fixture(7, dir);
    const Tracer tracer(fx.model, 1.0);
    const UncertaintyFade fade(fx.model, fx.channels, 0, 0, 100);
    Shading shading;
    shading.fade = &fade;
    const Frame &f = fx.voxels.frame;
    const Camera camera = sbrt_test::top_camera(f, f.top + 10);
    const Image image = shade(tracer, camera, trace_image(tracer, camera, 2), shading, 2);
    int faded = 0;
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            int top = -1;
            for (int z = f.depths - 1; z >= 0 && top < 0; --z)
                if (fx.voxels.classes[(size_t(z) * f.rows + row) * f.cols + col] != NULL_CLASS)
                    top = z;
            if (top < 0)
                continue;
            const size_t i = size_t(row) * size_t(f.cols) + size_t(col);
            const int32_t id = fx.voxels.classes[(size_t(top) * f.rows + row) * f.cols + col];
            const auto rgb = material_color(fx.model, uint32_t(fx.model.find_material(id)));
            glm::dvec3 want(rgb[0], rgb[1], rgb[2]);
            const float u = at(fx, 0, col, f.rows - 1 - row, top);
            if (u != FILL) {
                const double grey = 0.2126 * want.x + 0.7152 * want.y + 0.0722 * want.z;
                want += std::clamp(u / 100.0, 0.0, 1.0) * (glm::dvec3(grey) - want);
                faded += u > 0;
            }
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(image.rgb[i * 3 + size_t(k)], uint8_t(std::lround(want[k])))
                    << row << " " << col << " u " << u;
        }
    EXPECT_GT(faded, f.rows * f.cols / 3);
    EXPECT_THROW(UncertaintyFade(fx.model, fx.channels, 0, 5, 5), Error);
}
