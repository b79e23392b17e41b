/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Colours by voxel on the GPU (issue 29): a property of few
 *            whole values (a scaled sum with fills) and an uncertainty
 *            fade, shaded by the GPU (egl, llvmpipe here), against the
 *            CPU's image of the same renderer: from several sides, through
 *            clip planes and with strata hidden; where the GPU does not
 *            make them (value= output, kernel normals) the host does
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>
#include <memory>
#include <random>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "format/mapped_file.hpp"
#include "gpu/gpu_paint.hpp"
#include "gpu_compare.hpp"
#include "scene/hidden_materials.hpp"
#include "shading/property_paint.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

constexpr float FILL = -127;

/// A random voxel model with two channels: a percentage with fills and a
/// second one meant `b_scale` times its stored value (0 .. b_values - 1)
/// plus `b_offset`.
struct PaintFixture {
    Model model;
    std::shared_ptr<const PropertyChannels> channels;
};

PaintFixture fixture(const std::string &dir, double b_scale = 2, unsigned b_values = 40,
                     double b_offset = 0)
{
    PaintFixture fx;
    const Voxels voxels = random_voxels(5, 36, 44, 30, 6);
    fx.model = build_model(voxels);
    const Frame &f = voxels.frame;
    std::mt19937 rng(5);
    Source source(2, std::vector<float>(f.voxels()));
    for (size_t i = 0; i < f.voxels(); ++i) {
        source[0][i] = rng() % 11 == 0 ? FILL : float(rng() % 101);
        source[1][i] = float(rng() % b_values);
    }
    ChannelInfo a, b;
    a.name = "kans_5";
    a.has_fill = true;
    a.fill = FILL;
    b.name = "kans_6";
    b.scale = b_scale;
    b.offset = b_offset;
    const std::string path = dir + "/channels";
    write_channels(path, fx.model, source, {a, b}, 8);
    fx.channels = std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(path), path, fx.model);
    return fx;
}

ColorRamp ramp()
{
    return ColorRamp::through({{30, 0, 90}, {20, 160, 140}, {250, 230, 30}}, 0, 180);
}

/// EGL in both layouts, and with a GPU's branches (staged bands, no loop
/// budget).
class GpuPaint : public GpuVariantTest {};

INSTANTIATE_TEST_SUITE_P(
    Layouts, GpuPaint,
    ::testing::Values(GpuVariant{"egl", GpuLayout::ssbo}, GpuVariant{"egl", GpuLayout::textures},
                      GpuVariant{"egl", GpuLayout::ssbo, sbrt_gl::BandStaging::staged, true}),
    variant_name);

/// Cameras from above, low from the south-west and from the north-east.
std::vector<Camera> cameras(const Tracer &t)
{
    std::vector<Camera> out;
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -0.4, 1.2), glm::dvec3(-0.7, -0.6, 0.5),
                                 glm::dvec3(0.8, 0.5, 0.35)})
        out.push_back(Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() *
                                                                    glm::normalize(dir),
                                          t.frame().centre(), 40, 71, 93));
    return out;
}

/// Pixels whose colour differs by more than a level between two images.
size_t differing(const Image &a, const Image &b)
{
    size_t n = 0;
    for (size_t i = 0; i < a.rgb.size(); i += 3)
        for (int k = 0; k < 3; ++k)
            if (std::abs(int(a.rgb[i + k]) - int(b.rgb[i + k])) > 1) {
                ++n;
                break;
            }
    return n;
}

} // namespace

TEST_P(GpuPaint, APropertySumIsColouredOnTheGpuAsTheCpuDoes)
{
    const PaintFixture fx = fixture(temp_dir("gpu_paint_property"));
    const PropertyPaint paint(fx.model, fx.channels, {0, 1}, ramp());
    ASSERT_GT(paint.whole().count, 0u);
    Shading shading;
    shading.light = Shading::light_from(120, 40);
    shading.property = &paint;
    const Renderer renderer(fx.model, 2.0, Scene{}, shading, {2, true, 16});
    for (const Camera &camera : cameras(renderer.tracer()))
        expect_gpu_shading_as_cpu(*context_, GetParam().options(), renderer, camera, "property", 2);
    // the colours are the property's, not the classes'
    Shading classes = shading;
    classes.property = nullptr;
    const Renderer by_class(fx.model, 2.0, Scene{}, classes, {2, true, 16});
    const Camera camera = cameras(renderer.tracer())[0];
    const Image shown = renderer.render_image(camera, {});
    EXPECT_GT(differing(shown, by_class.render_image(camera, {})), shown.rgb.size() / 3 / 4);
}

TEST_P(GpuPaint, AFadeIsColouredOnTheGpuAsTheCpuDoes)
{
    const PaintFixture fx = fixture(temp_dir("gpu_paint_fade"));
    const UncertaintyFade fade(fx.model, fx.channels, 0, 0, 100);
    Shading shading;
    shading.light = Shading::light_from(200, 35);
    shading.fade = &fade;
    const Renderer renderer(fx.model, 2.0, Scene{}, shading, {2, true, 16});
    for (const Camera &camera : cameras(renderer.tracer()))
        expect_gpu_shading_as_cpu(*context_, GetParam().options(), renderer, camera, "fade", 2);
}

TEST_P(GpuPaint, AtAVoxelsEdgeTheGpuColoursWhereDoubleOrBothSidesSettleIt)
{
    // three values: neighbours often agree (the GPU colours those pixels
    // whichever side float puts the hit on); where they do not, the GPU
    // places the hit on its face again in double and colours it where it
    // lies well inside its voxel's face, else the host colours it.
    // Comparing the wrong neighbour, or none, or a wrong placement in
    // double, colours some of the ~1e-4 of pixels near an edge by the
    // wrong voxel.
    const Voxels voxels = random_voxels(9, 36, 44, 30, 6);
    const Model model = build_model(voxels);
    const Frame &f = voxels.frame;
    std::mt19937 rng(9);
    Source source(1, std::vector<float>(f.voxels()));
    for (float &v : source[0])
        v = float(rng() % 3);
    ChannelInfo info;
    info.name = "kans_1";
    const std::string path = temp_dir("gpu_paint_edges") + "/channels";
    write_channels(path, model, source, {info}, 8);
    const auto channels = std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(path), path, model);
    const PropertyPaint paint(model, channels, {0}, ColorRamp::through({{0, 0, 255}, {255, 0, 0}}, 0, 2));
    ASSERT_EQ(paint.whole().count, 3u);
    Shading shading;
    shading.property = &paint;
    const Renderer renderer(model, 2.0, Scene{}, shading, {2, true, 16});
    const Tracer &t = renderer.tracer();
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, GetParam().options());
    size_t sent_back = 0;
    for (const glm::dvec3 dir : {glm::dvec3(0.3, -0.4, 1.2), glm::dvec3(-0.7, -0.6, 0.5)}) {
        const Camera camera = Camera::perspective(
            t.frame().centre() + 2.2 * t.frame().radius() * glm::normalize(dir),
            t.frame().centre(), 40, 700, 900);
        ASSERT_TRUE(on_gpu.shades_on_gpu(camera));
        const Image want = renderer.render_image(camera, {true, false, false});
        const Image got = on_gpu.render_image(camera, {true, false, false}, 2);
        sent_back += on_gpu.gpu().stats().over_budget;
        size_t classes = 0, colours = 0;
        for (size_t i = 0; i < want.material.size(); ++i) {
            if (got.material[i] != want.material[i]) {
                ++classes;
                continue;
            }
            for (int k = 0; k < 3; ++k)
                if (std::abs(int(got.rgb[3 * i + k]) - int(want.rgb[3 * i + k])) > 1) {
                    ++colours;
                    break;
                }
        }
        EXPECT_LE(classes, want.material.size() / 5000);
        EXPECT_EQ(colours, 0u) << "pixels coloured by another voxel than the CPU's";
    }
    // some hits float puts across the edge from the CPU's go back to the
    // host; in double most settle on the GPU (26 here, 242 in float alone)
    EXPECT_GT(sent_back, 0u);
    EXPECT_LT(sent_back, 60u);
}

TEST_P(GpuPaint, CutsAndHiddenStrataShowTheValuesOfTheModelAsRead)
{
    const PaintFixture fx = fixture(temp_dir("gpu_paint_cuts"));
    const PropertyPaint paint(fx.model, fx.channels, {0, 1}, ramp());
    Shading shading;
    shading.property = &paint;
    const Frame &f = fx.model.frame();
    // off the cell walls and the voxels' tops
    const glm::dvec3 mid((f.west + f.east) / 2 + 0.37 * f.ew_res(),
                         (f.south + f.north) / 2 + 0.29 * f.ns_res(),
                         (f.bottom + f.top) / 2 + 0.41 * f.tb_res());
    Scene cut;
    cut.planes = {{mid, {1, -0.6, 0.2}}, {mid + glm::dvec3(0, 8 * f.ns_res(), 0), {0, 1, 0}}};
    const Renderer sections(hide_materials(fx.model, {2}), 2.0, cut, shading, {2, true, 16});
    for (const Camera &camera : cameras(sections.tracer()))
        expect_gpu_shading_as_cpu(*context_, GetParam().options(), sections, camera, "cuts", 2);
}

TEST_P(GpuPaint, WhatTheGpuDoesNotColourTheHostDoes)
{
    const PaintFixture fx = fixture(temp_dir("gpu_paint_host"));
    const PropertyPaint paint(fx.model, fx.channels, {0, 1}, ramp());
    Shading shading;
    shading.property = &paint;
    const Renderer renderer(fx.model, 2.0, Scene{}, shading, {2, true, 16});
    const Camera camera = cameras(renderer.tracer())[1];
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, GetParam().options());
    EXPECT_TRUE(on_gpu.shades_on_gpu(camera));
    // value=: the property at each hit, which the GPU does not write
    Outputs value;
    value.value = true;
    EXPECT_FALSE(on_gpu.shades_on_gpu(camera, value));
    const Image want = renderer.render_image(camera, value);
    const Image got = on_gpu.render_image(camera, value);
    ASSERT_EQ(got.value.size(), want.value.size());
    size_t same = 0;
    for (size_t i = 0; i < want.value.size(); ++i)
        same += got.value[i] == want.value[i] ||
                (std::isnan(got.value[i]) && std::isnan(want.value[i]));
    EXPECT_GE(same, want.value.size() - want.value.size() / 500);
    // a property of other than few whole values: the host
    const PropertyPaint one(fx.model, fx.channels, {0}, ramp());
    Shading kernel = shading;
    kernel.property = &one;
    kernel.normals = Normals::kernel;
    EXPECT_FALSE(gpu_paints(renderer.tracer(), kernel, {}));
}

TEST(GpuPaintWords, EachVoxelHoldsItsEntryAndEachCellItsSpan)
{
    // the entries in integers (whole 1-byte codes, a small scale; 2-byte
    // codes with an offset), and through the doubles of sum_at (a scale
    // too large for the integers' bounds); columns of up to 30 voxels: runs
    // of 16 and the rest
    struct Case {
        double scale;
        unsigned values;
        double offset;
    };
    for (const Case &c : {Case{2, 40, 0}, Case{1, 300, 7}, Case{2000, 4, 0}}) {
        SCOPED_TRACE("second channel: scale " + std::to_string(c.scale) + ", " +
                     std::to_string(c.values) + " values, offset " + std::to_string(c.offset));
        const PaintFixture fx = fixture(temp_dir("gpu_paint_words"), c.scale, c.values, c.offset);
        const PropertyPaint paint(fx.model, fx.channels, {0, 1}, ramp());
        ASSERT_GT(paint.whole().count, 0u);
        Shading shading;
        shading.property = &paint;
        const Tracer tracer(fx.model, 1.0);
        const std::vector<uint32_t> words = make_gpu_paint(tracer, shading, 2);
        const Frame &f = fx.model.frame();
        size_t checked = 0;
        for (uint64_t cell = 0; cell < f.cells(); ++cell) {
            const ColumnSpan span = fx.channels->span(cell);
            ASSERT_EQ(words[5 + 2 * cell], span.lo | span.hi << 16);
            for (uint32_t level = span.lo; level < span.hi; ++level) {
                const uint32_t i = words[4 + 2 * cell] + level - span.lo;
                const uint32_t entry = (words[words[0] + i / 2] >> (16 * (i & 1))) & 0xffff;
                double v;
                if (!paint.voxel_value({cell, level}, v)) {
                    EXPECT_EQ(entry, GPU_PAINT_NONE);
                    continue;
                }
                ASSERT_EQ(double(entry), v - paint.whole().low);
                // its colour: the ramp's at the value
                float rgb[3];
                std::memcpy(rgb, &words[words[1] + 3 * entry], sizeof rgb);
                const glm::dvec3 want = paint.ramp().at(v);
                for (int k = 0; k < 3; ++k)
                    EXPECT_FLOAT_EQ(rgb[k], float(want[k]));
                ++checked;
            }
        }
        EXPECT_GT(checked, f.cells() * 4);
        EXPECT_EQ(words[3], uint32_t(paint.whole().count)); // the no-value colour
    }
}

TEST(GpuPaintWords, OnlyTheSummedChannelsBlocksThatHoldVoxelsAreDecoded)
{
    // voxels in the north-west corner only (as in a model read for an
    // area): the words decode the blocks of the summed channels there,
    // none of the third channel, none elsewhere
    Voxels voxels = random_voxels(7, 36, 44, 30, 6);
    const Frame &f = voxels.frame;
    for (int d = 0; d < f.depths; ++d)
        for (int r = 0; r < f.rows; ++r)
            for (int c = 0; c < f.cols; ++c)
                if (r >= 12 || c >= 10)
                    voxels.classes[size_t(d) * f.cells() + size_t(r) * size_t(f.cols) + size_t(c)] =
                        NULL_CLASS;
    const Model model = build_model(voxels);
    std::mt19937 rng(9);
    Source source(3, std::vector<float>(f.voxels()));
    for (std::vector<float> &channel : source)
        for (float &v : channel)
            v = float(rng() % 101);
    std::vector<ChannelInfo> infos(3);
    infos[0].name = "a";
    infos[1].name = "b";
    infos[2].name = "c";
    const std::string path = temp_dir("gpu_paint_blocks") + "/channels";
    write_channels(path, model, source, infos, 8);
    const auto channels = std::make_shared<const PropertyChannels>(
        std::make_shared<const MappedFile>(path), path, model);
    std::set<size_t> with_voxels;
    for (uint64_t cell = 0; cell < f.cells(); ++cell)
        if (channels->span(cell).size() > 0)
            with_voxels.insert(channels->block_of(cell));
    ASSERT_GE(with_voxels.size(), 2u);
    ASSERT_LT(with_voxels.size(), channels->blocks() / 4);
    const PropertyPaint paint(model, channels, {0, 2}, ramp());
    Shading shading;
    shading.property = &paint;
    const Tracer tracer(model, 1.0);
    EXPECT_EQ(channels->blocks_decoded(), 0u);
    make_gpu_paint(tracer, shading, 3);
    EXPECT_EQ(channels->blocks_decoded(), 2 * with_voxels.size());
}

