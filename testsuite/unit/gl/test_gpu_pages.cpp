/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A model read block by block on the GPU (issue 49): its blocks
 *            brought up as the rays want them, into an atlas of a budget;
 *            hits and frames those of the model uploaded whole, bit for
 *            bit, and with an atlas of a few blocks still the CPU's
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_compare.hpp"
#include "gpu_internal.hpp"
#include "gpu_page_atlas.hpp"
#include "paged_case.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

class GpuPages : public GpuVariantTest {
protected:
    /// The variant's options with `budget` bytes of GPU memory.
    sbrt_gl::GpuOptions options(uint64_t budget) const
    {
        sbrt_gl::GpuOptions o = GetParam().options();
        o.page_budget_bytes = budget;
        return o;
    }
};

/// EGL as the GL calls for, then a GPU's branches: bands staged, no loop
/// budget.
std::vector<GpuVariant> page_variants()
{
    using sbrt_gl::BandStaging;
    return {{"egl"},
            {"egl", GpuLayout::ssbo, BandStaging::staged},
            {"egl", GpuLayout::ssbo, BandStaging::direct, true}};
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuPages, ::testing::ValuesIn(page_variants()), variant_name);

/// Cameras around the model, above it, low over it and inside its box.
std::vector<Camera> cameras(const Tracer &t, int rows, int cols)
{
    const glm::dvec3 c = t.frame().centre();
    const double r = t.frame().radius();
    std::vector<Camera> out;
    for (const glm::dvec3 &from :
         {glm::dvec3(0.6, -0.7, 0.5), glm::dvec3(-0.8, 0.3, 0.4), glm::dvec3(0.05, 0.02, 1.0),
          glm::dvec3(0.9, 0.9, 0.08)})
        out.push_back(Camera::perspective(c + 2.2 * r * from, c, 40, rows, cols));
    out.push_back(Camera::perspective(c + glm::dvec3(0.1, 0.2, 0.05) * r, c + glm::dvec3(r, 0, 0),
                                      60, rows, cols));
    return out;
}

/// The bytes of each output of two images, equal.
void expect_same_image(const Image &want, const Image &got, const std::string &what)
{
    EXPECT_EQ(want.rgb, got.rgb) << what;
    EXPECT_EQ(want.material, got.material) << what;
    ASSERT_EQ(want.elevation.size(), got.elevation.size()) << what;
    EXPECT_EQ(std::memcmp(want.elevation.data(), got.elevation.data(),
                          want.elevation.size() * sizeof(double)),
              0)
        << what;
    EXPECT_EQ(std::memcmp(want.depth.data(), got.depth.data(), want.depth.size() * sizeof(double)),
              0)
        << what;
}

constexpr uint64_t WHOLE_BUDGET = uint64_t(1) << 30;

/// A scene of `model` with the materials `hidden` hidden (crossed as air).
Scene hiding(const Model &model, std::initializer_list<int> hidden)
{
    Scene scene;
    scene.hidden.assign(model.materials().size(), 0);
    for (int m : hidden)
        scene.hidden[size_t(m)] = 1;
    return scene;
}

/// A budget of GPU memory for `t`'s paged model: its pyramid (at most half
/// of it) and room for `blocks` of `c`'s largest blocks.
uint64_t budget_for_blocks(const PagedCase &c, const Tracer &t, int blocks)
{
    const uint64_t pyramid = gpu_pyramid_bytes(t.pyramid());
    return std::max(2 * pyramid + 1024, pyramid + 1024 + uint64_t(blocks) * c.largest_block());
}

} // namespace

/// The hits of the paged model `paged` on the GPU against the whole
/// model's, bit for bit, from every camera; the blocks it brought up.
uint64_t expect_hits_of_the_whole(const sbrt_gl::GlContext &context, const PagedCase &c,
                                  const Model &paged, const Scene &scene,
                                  const sbrt_gl::GpuOptions &options)
{
    const Tracer paged_tracer(paged, 1.5, scene), whole_tracer(c.model, 1.5, scene);
    sbrt_gl::GpuTracer on_pages(context, paged_tracer, options);
    sbrt_gl::GpuTracer whole(context, whole_tracer, options);
    EXPECT_NE(on_pages.model().pages(), nullptr);
    EXPECT_EQ(whole.model().pages(), nullptr);
    size_t hits = 0;
    for (const Camera &camera : cameras(whole_tracer, 37, 41)) {
        expect_same_hits(whole.trace_image(camera, 2), on_pages.trace_image(camera, 2), hits);
        if (::testing::Test::HasFatalFailure())
            return 0;
    }
    EXPECT_GT(hits, 1000u);
    // the first frame brought its blocks up in passes again; some stay
    EXPECT_GT(on_pages.model().pages()->held_blocks(), 0);
    return on_pages.model().pages()->figures().uploads;
}

TEST_P(GpuPages, HitsOfAPagedModelAreTheWholeModelsBitForBit)
{
    const PagedCase c;
    const Scene hidden = hiding(c.model, {1, 2});
    // a plane, and material 1 translucent
    const Scene translucent = cut_and_translucent_scene(c.model);
    bool plain = true;
    for (const Scene &scene : {Scene{}, hidden, translucent}) {
        const uint64_t without = expect_hits_of_the_whole(
            *context_, c, c.paged(WHOLE_BUDGET), scene, options(WHOLE_BUDGET));
        // the columns' top intervals on the GPU: a ray that meets only the
        // top interval reads no block, and the hits stay the same
        const Model with_tops = c.paged(WHOLE_BUDGET, true);
        ASSERT_TRUE(with_tops.pages()->has_column_tops());
        const uint64_t with = expect_hits_of_the_whole(*context_, c, with_tops, scene,
                                                       options(WHOLE_BUDGET));
        EXPECT_GT(without, 0u);
        // 23 of 30 blocks where every stratum shows
        if (plain) {
            EXPECT_LT(with, without);
        }
        EXPECT_LE(with, without);
        plain = false;
    }
}

TEST_P(GpuPages, ShadedFramesOfAPagedModelAreTheWholeModelsByteForByte)
{
    const PagedCase c;
    Shading lit;
    lit.light = Shading::light_from(300, 35);
    const Outputs all{true, true, true};
    const Renderer paged(c.paged(WHOLE_BUDGET), 1.5, Scene{}, lit, {2, true, 8});
    const Renderer whole(c.model, 1.5, Scene{}, lit, {2, true, 8});
    sbrt_gl::GpuRenderer on_pages(*context_, paged, options(WHOLE_BUDGET));
    sbrt_gl::GpuRenderer on_whole(*context_, whole, options(WHOLE_BUDGET));
    int k = 0;
    for (const Camera &camera : cameras(whole.tracer(), 43, 39)) {
        const std::string what = "camera " + std::to_string(k++);
        expect_same_image(on_whole.render_image(camera, all, 2),
                          on_pages.render_image(camera, all, 2), what);
    }
    // the same frame again: every block it needs is up, no pass again
    const Camera camera = cameras(whole.tracer(), 43, 39).front();
    on_pages.render_image(camera, all, 2);
    const uint64_t uploads = on_pages.gpu().model().pages()->figures().uploads;
    Image image = empty_image(camera, all);
    const sbrt_gl::GpuFrameReport r =
        on_pages.render(camera, all, [&](const Band &band) { gather_band(band, image); }, 2);
    EXPECT_EQ(r.gpu.page_passes, 0);
    EXPECT_EQ(on_pages.gpu().model().pages()->figures().uploads, uploads);
}

TEST_P(GpuPages, AnAtlasOfAFewBlocksHoldsItsBudgetAndTheFrameStaysExact)
{
    const PagedCase c;
    const Outputs all{true, true, true};
    const Renderer paged(c.paged(WHOLE_BUDGET), 1.5, Scene{}, Shading{}, {2, true, 8});
    const uint64_t budget = budget_for_blocks(c, paged.tracer(), 3);
    sbrt_gl::GpuRenderer on_pages(*context_, paged, options(budget));
    const sbrt_gl::GpuPageAtlas &atlas = *on_pages.gpu().model().pages();
    EXPECT_LE(on_pages.gpu().memory().total() + on_pages.gpu().pyramid_bytes(), budget);
    const double tolerance = 2e-5 * 2 * paged.tracer().frame().radius();
    int k = 0;
    size_t sent_to_host = 0;
    for (const Camera &camera : cameras(paged.tracer(), 43, 39)) {
        Image got = empty_image(camera, all);
        const sbrt_gl::GpuFrameReport r =
            on_pages.render(camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
        sent_to_host += r.gpu.over_budget;
        expect_images_agree(paged.render_image(camera, all), got, tolerance,
                            "camera " + std::to_string(k++));
        EXPECT_LE(atlas.held_bytes(), atlas.atlas_bytes());
    }
    // views that want more blocks than the atlas holds: the rest on the host
    EXPECT_GT(sent_to_host, 0u);
    // kernel normals: records sent back would show nothing to their
    // neighbours' kernels, so the host finds the normals from the GPU's hits
    Shading kernel;
    kernel.normals = Normals::kernel;
    const Renderer kernel_paged(c.paged(WHOLE_BUDGET), 1.5, Scene{}, kernel, {2, true, 8});
    sbrt_gl::GpuRenderer kernel_on_pages(*context_, kernel_paged, options(budget));
    int on_host = 0;
    for (const Camera &camera : cameras(paged.tracer(), 43, 39)) {
        Image got = empty_image(camera, all);
        const sbrt_gl::GpuFrameReport r = kernel_on_pages.render(
            camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
        on_host += r.shaded_on_gpu ? 0 : 1;
        expect_images_agree(kernel_paged.render_image(camera, all), got, tolerance, "kernel");
    }
    EXPECT_GT(on_host, 0);
    EXPECT_GT(atlas.figures().dropped + atlas.figures().not_placed, 0u);
    // records too (kernel normals and the hits' path)
    const Tracer &t = paged.tracer();
    sbrt_gl::GpuTracer records(*context_, t, options(budget));
    for (const Camera &camera : cameras(t, 31, 29)) {
        const Agreement a = compare(records, t, camera);
        EXPECT_EQ(a.same_material, a.pixels);
        EXPECT_EQ(a.agreeing, a.pixels);
    }
}

TEST_P(GpuPages, BandByBandAFrameWhoseBlocksExceedTheAtlasStaysOnTheGpu)
{
    const PagedCase c;
    const Outputs all{true, true, true};
    // room for four blocks: a frame wants more, a band of four rows fewer
    const Renderer probe(c.paged(WHOLE_BUDGET), 1.5, Scene{}, Shading{}, {2, true, 4});
    const uint64_t budget = budget_for_blocks(c, probe.tracer(), 4);
    const double tolerance = 2e-5 * 2 * probe.tracer().frame().radius();
    // the whole frame as one band; in bands of four rows; in bands as the
    // tracer chooses them, of four rows once the atlas was found crowded
    const int band_rows[3] = {64, 4, 0};
    uint32_t sent_to_host[3] = {0, 0, 0};
    uint64_t restarts[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        const Renderer paged(c.paged(WHOLE_BUDGET), 1.5, Scene{}, Shading{},
                             {2, true, band_rows[k]});
        sbrt_gl::GpuOptions o = options(budget);
        o.crowded_band_pixels = 4 * 39;
        sbrt_gl::GpuRenderer on_pages(*context_, paged, o);
        for (const Camera &camera : cameras(paged.tracer(), 43, 39)) {
            Image got = empty_image(camera, all);
            const sbrt_gl::GpuFrameReport r = on_pages.render(
                camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
            sent_to_host[k] += r.gpu.over_budget;
            expect_images_agree(paged.render_image(camera, all), got, tolerance,
                                "bands of " + std::to_string(band_rows[k]) + " rows");
        }
        restarts[k] = on_pages.gpu().model().pages()->figures().band_restarts;
    }
    // one band: a band that found no room has no earlier band's blocks
    // to let go, and its rays go to the host; in bands, each band's blocks
    // push out the earlier bands' (2004 rays on the host, 292 in bands)
    EXPECT_GT(sent_to_host[0], 0u);
    EXPECT_GT(restarts[1], 0u);
    EXPECT_LT(sent_to_host[1] * 2, sent_to_host[0]);
    EXPECT_GT(restarts[2], 0u);
    EXPECT_LT(sent_to_host[2], sent_to_host[0]);
}

TEST_P(GpuPages, ColumnsInPagesGiveTheWholeModelsHitsAndFrames)
{
    const PagedCase c;
    const Model paged = c.paged(WHOLE_BUDGET, true);
    const Scene hidden = hiding(c.model, {1, 2});
    const Scene translucent = cut_and_translucent_scene(c.model);
    // the pyramid from level 1, 2 and 3 on: the columns' pages give level
    // 0, and the levels between are not on the GPU
    for (int level : {1, 2, 3}) {
        sbrt_gl::GpuOptions o = options(WHOLE_BUDGET);
        o.column_pages_from_level = level;
        {
            const Tracer t(paged, 1.5);
            const sbrt_gl::GpuTracer gpu(*context_, t, o);
            EXPECT_TRUE(gpu.model().form().column_pages);
            EXPECT_EQ(gpu.pyramid_bytes(), gpu_pyramid_bytes(t.pyramid(), level));
        }
        for (const Scene &scene : {Scene{}, hidden, translucent}) {
            expect_hits_of_the_whole(*context_, c, paged, scene, o);
            ASSERT_FALSE(HasFatalFailure()) << "from level " << level;
        }
    }
    // shaded frames (the first pass stops at the first level held)
    Shading lit;
    lit.light = Shading::light_from(300, 35);
    const Outputs all{true, true, true};
    const Renderer on_columns(paged, 1.5, Scene{}, lit, {2, true, 8});
    const Renderer whole(c.model, 1.5, Scene{}, lit, {2, true, 8});
    sbrt_gl::GpuOptions o = options(WHOLE_BUDGET);
    o.column_pages_from_level = 2;
    sbrt_gl::GpuRenderer gpu_columns(*context_, on_columns, o);
    sbrt_gl::GpuRenderer gpu_whole(*context_, whole, options(WHOLE_BUDGET));
    int k = 0;
    for (const Camera &camera : cameras(whole.tracer(), 43, 39))
        expect_same_image(gpu_whole.render_image(camera, all, 2),
                          gpu_columns.render_image(camera, all, 2),
                          "camera " + std::to_string(k++));
}

TEST_P(GpuPages, ColumnsInPagesOfAWideModelGiveItsHitsBitForBit)
{
    // two words a column's top interval and two its range: tops that are
    // no voxel boundaries
    const PagedCase c(float_model(37, 45, 6, 5));
    const Model paged = c.paged(WHOLE_BUDGET, true);
    ASSERT_FALSE(sbrt_gl::compact_on_gpu(paged));
    for (int level : {1, 2, 3}) {
        sbrt_gl::GpuOptions o = options(WHOLE_BUDGET);
        o.column_pages_from_level = level;
        expect_hits_of_the_whole(*context_, c, paged, Scene{}, o);
        ASSERT_FALSE(HasFatalFailure()) << "from level " << level;
    }
    // whole, beside the pyramid's levels above
    expect_hits_of_the_whole(*context_, c, paged, Scene{}, options(WHOLE_BUDGET));
}

TEST_P(GpuPages, APyramidOverHalfTheBudgetPagesTheColumnsAndStaysExact)
{
    const PagedCase c;
    const Outputs all{true, true, true};
    const Renderer paged(c.paged(WHOLE_BUDGET, true), 1.5, Scene{}, Shading{}, {2, true, 8});
    const Tracer &t = paged.tracer();
    // below twice the pyramid, a quarter of it holds the pyramid from
    // level 1 on
    const uint64_t whole = gpu_pyramid_bytes(t.pyramid());
    const uint64_t budget = 2 * whole - 8;
    ASSERT_LE(gpu_pyramid_bytes(t.pyramid(), 1), budget / 4);
    sbrt_gl::GpuRenderer on_pages(*context_, paged, options(budget));
    const sbrt_gl::GpuModel &model = on_pages.gpu().model();
    EXPECT_TRUE(model.form().column_pages);
    EXPECT_EQ(model.pyramid_bytes(), gpu_pyramid_bytes(t.pyramid(), 1));
    EXPECT_LE(on_pages.gpu().memory().total() + model.pyramid_bytes(), budget);
    const double tolerance = 2e-5 * 2 * t.frame().radius();
    int k = 0;
    for (const Camera &camera : cameras(t, 43, 39))
        expect_images_agree(paged.render_image(camera, all), on_pages.render_image(camera, all, 2),
                            tolerance, "camera " + std::to_string(k++));
    EXPECT_GT(model.pages()->figures().uploads, 0u);
}

TEST_P(GpuPages, AnotherSceneOfTheModelTakesOverItsBlocksOnTheGpu)
{
    const PagedCase c;
    const Model paged = c.paged(WHOLE_BUDGET, true);
    const Scene hidden = hiding(c.model, {1});
    std::shared_ptr<sbrt_gl::GpuPageAtlas> kept;
    sbrt_gl::GpuOptions keeping = options(WHOLE_BUDGET);
    keeping.kept_atlas = &kept;
    const Tracer plain_tracer(paged, 1.5);
    const Camera camera = cameras(plain_tracer, 37, 41).front();
    uint64_t uploads = 0;
    {
        sbrt_gl::GpuTracer plain(*context_, plain_tracer, keeping);
        plain.trace_image(camera, 2);
        uploads = plain.model().pages()->figures().uploads;
        ASSERT_GT(uploads, 0u);
    }
    ASSERT_NE(kept, nullptr); // the tracer is gone, its blocks stay
    const sbrt_gl::GpuPageAtlas *atlas = kept.get();
    // a stratum hidden: a new tracer, the same atlas, no block up again
    const Tracer hidden_tracer(paged, 1.5, hidden), whole_hidden(c.model, 1.5, hidden);
    sbrt_gl::GpuTracer again(*context_, hidden_tracer, keeping);
    EXPECT_EQ(again.model().pages(), atlas);
    sbrt_gl::GpuTracer whole(*context_, whole_hidden, options(WHOLE_BUDGET));
    size_t hits = 0;
    expect_same_hits(whole.trace_image(camera, 2), again.trace_image(camera, 2), hits);
    ASSERT_FALSE(HasFatalFailure());
    const uint64_t more = again.model().pages()->figures().uploads - uploads;
    EXPECT_LT(more, uploads); // only the blocks the hidden stratum opens
    // another model's tracer does not take it
    const Model other = c.paged(WHOLE_BUDGET, true);
    const Tracer other_tracer(other, 1.5);
    sbrt_gl::GpuTracer elsewhere(*context_, other_tracer, keeping);
    EXPECT_NE(elsewhere.model().pages(), atlas);
}

TEST_P(GpuPages, APagedModelIsRefusedWhereTheGpuCannotPageIt)
{
    const PagedCase c;
    const Model paged = c.paged(WHOLE_BUDGET);
    const Tracer tracer(paged, 1.0);
    sbrt_gl::GpuOptions textures = options(WHOLE_BUDGET);
    textures.layout = GpuLayout::textures;
    try {
        sbrt_gl::GpuTracer gpu(*context_, tracer, textures);
        ADD_FAILURE() << "textures accepted";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("layout=ssbo"), std::string::npos) << e.what();
    }
    // a budget whose half the pyramid exceeds (checked before its words
    // are made): an error that names gpu_memory
    const uint64_t pyramid = gpu_pyramid_bytes(tracer.pyramid());
    EXPECT_EQ(pyramid, make_gpu_pyramid(tracer.pyramid()).size() * 4);
    try {
        sbrt_gl::GpuTracer gpu(*context_, tracer, options(2 * pyramid - 2));
        ADD_FAILURE() << "a budget below twice the pyramid accepted";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("gpu_memory"), std::string::npos) << e.what();
    }
    sbrt_gl::GpuTracer fits(*context_, tracer, options(2 * pyramid));
    EXPECT_LE(fits.memory().total() + fits.pyramid_bytes(), 2 * pyramid);
}
