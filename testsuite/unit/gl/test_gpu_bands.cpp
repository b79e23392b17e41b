/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The GPU's shaded bands where the host reads them (issue 32):
 *            the band layout (RGB rows on whole words, the planes asked
 *            for and no others), the mapped bands equal to the CPU's image
 *            for image widths that are not a multiple of 4 and bands of
 *            any height, rays over the loop budget traced on the host, the
 *            bytes the host touches per pixel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gpu/gpu_layout.hpp"
#include "gpu/gpu_overlays.hpp"
#include "tracing/cpu_tracing.hpp"
#include "gpu_compare.hpp"
#include "gl_context.hpp"
#include "gpu_options.hpp"
#include "gpu_renderer.hpp"
#include "renderer.hpp"
#include "test_support.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

TEST(GpuBandLayout, RgbRowsStartOnWholeWordsAndOnlyTheOutputsAskedForFollow)
{
    for (int cols : {1, 2, 3, 4, 5, 61, 1056}) {
        const GpuBandLayout rgb = gpu_band_layout(7, cols, Outputs{});
        EXPECT_EQ(rgb.rgb_stride_words * 4, (size_t(cols) * 3 + 3) / 4 * 4) << cols;
        EXPECT_GE(rgb.rgb_stride_words * 4, size_t(cols) * 3) << cols;
        EXPECT_EQ(rgb.material_at, 0u);
        EXPECT_EQ(rgb.elevation_at, 0u);
        EXPECT_EQ(rgb.depth_at, 0u);
        // the count of rays over the budget and room for every pixel
        EXPECT_EQ(rgb.words, rgb.over_budget_at + 1 + 7 * size_t(cols));
        EXPECT_GE(rgb.over_budget_at, rgb.rgb_stride_words * 7);

        const GpuBandLayout all = gpu_band_layout(7, cols, Outputs{true, true, true});
        const size_t pixels = 7 * size_t(cols);
        EXPECT_GE(all.material_at, all.rgb_stride_words * 7);
        EXPECT_GE(all.elevation_at, all.material_at + pixels);
        EXPECT_GE(all.depth_at, all.elevation_at + 2 * pixels);
        EXPECT_GE(all.over_budget_at, all.depth_at + 2 * pixels);
        // doubles on 8 bytes
        EXPECT_EQ(all.elevation_at % 2, 0u) << cols;
        EXPECT_EQ(all.depth_at % 2, 0u) << cols;
    }
    GpuShade shade{};
    const GpuBandLayout l = gpu_band_layout(3, 5, Outputs{true, false, true});
    set_band_planes(shade, l);
    EXPECT_EQ(shade.outputs[0], l.rgb_stride_words);
    EXPECT_EQ(shade.planes[0], l.material_at);
    EXPECT_EQ(shade.planes[1], 0u);
    EXPECT_EQ(shade.planes[2], l.depth_at);
    EXPECT_EQ(shade.planes[3], l.over_budget_at);
}

/// Each GL backend as it calls for, and EGL in both band modes and without
/// a loop budget.
TEST(GpuOptions, TheBandsComeFromTheEnvironmentWhereSet)
{
    // SBRT_GPU_BANDS (measurements: device_run.sh) over the GL's choice
    const char *was = std::getenv("SBRT_GPU_BANDS");
    const std::string kept = was ? was : "";
    const auto bands_with = [](const char *value) {
        if (value)
            setenv("SBRT_GPU_BANDS", value, 1);
        else
            unsetenv("SBRT_GPU_BANDS");
        return sbrt_gl::GpuOptions::from_environment(GpuLayout::textures);
    };
    EXPECT_EQ(bands_with(nullptr).bands, sbrt_gl::BandStaging::automatic);
    EXPECT_EQ(bands_with("staged").bands, sbrt_gl::BandStaging::staged);
    EXPECT_EQ(bands_with("direct").bands, sbrt_gl::BandStaging::direct);
    EXPECT_EQ(bands_with("sideways").bands, sbrt_gl::BandStaging::automatic);
    EXPECT_EQ(bands_with(nullptr).layout, GpuLayout::textures);
    EXPECT_FALSE(bands_with(nullptr).loop_budget.has_value());
    EXPECT_TRUE(sbrt_gl::staged_bands({}, "NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(sbrt_gl::staged_bands({}, "llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_EQ(sbrt_gl::loop_budget({}, "NVIDIA H200/PCIe/SSE2"), sbrt_gl::UNBOUNDED_LOOP_BUDGET);
    EXPECT_EQ(sbrt_gl::loop_budget({}, "llvmpipe (LLVM 15.0.6, 256 bits)"), GPU_LOOP_BUDGET);
    if (was)
        setenv("SBRT_GPU_BANDS", kept.c_str(), 1);
    else
        unsetenv("SBRT_GPU_BANDS");
}

class GpuBands : public GpuVariantTest {};

std::vector<GpuVariant> band_variants()
{
    using sbrt_gl::BandStaging;
    std::vector<GpuVariant> out = {{"egl"}};
#ifdef SBRT_HAVE_OSMESA
    out.push_back({"osmesa"});
#endif
    out.push_back({"egl", GpuLayout::ssbo, BandStaging::staged});
    out.push_back({"egl", GpuLayout::ssbo, BandStaging::direct, true});
    return out;
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuBands, ::testing::ValuesIn(band_variants()), variant_name);

TEST_P(GpuBands, TheOptionsChooseTheBandsAndTheLoopBudget)
{
    // what the variant asks for, else what the GL calls for: llvmpipe's
    // bands written in place and a loop budget, a GPU's staged and none
    const Model m = geology(8, 8, 6);
    const Tracer tracer(m, 1.0);
    const GpuVariant &v = GetParam();
    const sbrt_gl::GpuTracer gpu(*context_, tracer, v.options());
    const bool software = sbrt_gl::is_software_renderer(gpu.gl_renderer());
    const bool staged = v.bands == sbrt_gl::BandStaging::automatic
                            ? !software
                            : v.bands == sbrt_gl::BandStaging::staged;
    EXPECT_EQ(gpu.staged_bands(), staged);
    EXPECT_EQ(gpu.loop_budget(), v.unbounded || !software ? sbrt_gl::UNBOUNDED_LOOP_BUDGET
                                                          : GPU_LOOP_BUDGET);
    EXPECT_EQ(sbrt_gl::GpuTracer(*context_, tracer, v.options(7)).loop_budget(), 7u);
}

TEST_P(GpuBands, MappedBandsOfAnyWidthAndHeightAreTheCpusImage)
{
    const Model m = geology(30, 44, 24);
    Shading lit;
    lit.light = Shading::light_from(300, 35);
    lit.background = {10, 20, 30};
    const Outputs all{true, true, true};
    for (int band_rows : {1, 5, 16, 0}) {
        const Renderer renderer(m, 2.0, Scene{}, lit, {2, true, band_rows});
        const Tracer &t = renderer.tracer();
        sbrt_gl::GpuRenderer on_gpu(*context_, renderer, options());
        const double tolerance = 2e-5 * 2 * t.frame().radius();
        for (int cols : {37, 38, 39, 40}) {
            const glm::dvec3 c = t.frame().centre();
            const Camera camera = Camera::perspective(
                c + 2.2 * t.frame().radius() * glm::dvec3(0.6, -0.7, 0.5), c, 40, 29, cols);
            const std::string what =
                "cols " + std::to_string(cols) + ", band rows " + std::to_string(band_rows);
            Image got = empty_image(camera, all);
            size_t strides_checked = 0;
            const sbrt_gl::GpuFrameReport r = on_gpu.render(
                camera, all,
                [&](const Band &band) {
                    // the band views the GPU's words: RGB rows on whole words
                    EXPECT_EQ(band.rgb.stride(), (size_t(cols) * 3 + 3) / 4 * 4) << what;
                    EXPECT_EQ(band.material.stride(), size_t(cols)) << what;
                    ++strides_checked;
                    gather_band(band, got);
                },
                2);
            EXPECT_TRUE(r.shaded_on_gpu) << what;
            EXPECT_GT(strides_checked, 0u);
            expect_images_agree(renderer.render_image(camera, all), got, tolerance, what);
            // the host read what was asked for: 3 + 4 + 8 + 8 bytes a pixel
            // and a count of rays over the budget a band
            const size_t pixels = size_t(cols) * 29;
            EXPECT_EQ(r.gpu.host_bytes, pixels * 23 + 4 * size_t(r.gpu.bands)) << what;
        }
    }
}

TEST_P(GpuBands, ShadedRaysOverTheLoopBudgetAreTracedAndShadedOnTheHost)
{
    const Model m = geology(40, 50, 20);
    const Renderer renderer(m, 1.0, Scene{}, Shading{}, {2, true, 8});
    const Tracer &t = renderer.tracer();
    // a budget of 4: many rays give up on the GPU
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, GetParam().options(4));
    const glm::dvec3 c = t.frame().centre();
    const Camera camera =
        Camera::perspective(c + glm::dvec3(-0.4, -0.5, 0.3) * 2.0 * t.frame().radius(), c, 40,
                            43, 61);
    const Outputs all{true, true, true};
    const Image want = renderer.render_image(camera, all);
    Image got = empty_image(camera, all);
    const sbrt_gl::GpuFrameReport r =
        on_gpu.render(camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
    const size_t pixels = size_t(camera.rows()) * size_t(camera.cols());
    EXPECT_GT(r.gpu.over_budget, pixels / 20);
    expect_images_agree(want, got, 2e-5 * 2 * t.frame().radius(), "budget of 4");
}

TEST_P(GpuBands, AnRgbFrameHandsTheHostThreeBytesAPixel)
{
    const Model m = geology(30, 44, 24);
    const Renderer renderer(m, 2.0, Scene{}, Shading{}, {2, true, 0});
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, options());
    const Tracer &t = renderer.tracer();
    const glm::dvec3 c = t.frame().centre();
    const Camera camera =
        Camera::perspective(c + 2.2 * t.frame().radius() * glm::dvec3(0.6, -0.7, 0.5), c, 40,
                            57, 83);
    size_t bands = 0;
    const sbrt_gl::GpuFrameReport r = on_gpu.render(
        camera, {},
        [&](const Band &band) {
            ++bands;
            EXPECT_TRUE(band.material.empty());
            EXPECT_TRUE(band.elevation.empty());
            EXPECT_TRUE(band.depth.empty());
            EXPECT_EQ(band.bytes_per_pixel(), 3u);
        },
        2);
    EXPECT_EQ(bands, size_t(r.gpu.bands));
    EXPECT_EQ(r.gpu.host_bytes, size_t(83 * 57) * 3 + 4 * bands);
    EXPECT_EQ(r.gpu.over_budget, 0u);
}

} // namespace

namespace {

TEST(OverlayTiles, EveryPixelWhoseRayMeetsABoxLiesInATileOfIt)
{
    // a thin tall box seen obliquely: its tiles are far fewer than those
    // of its bounding rectangle, and hold every pixel whose ray meets it
    const std::array<glm::dvec3, 2> box = {glm::dvec3(10, 10, 0), glm::dvec3(11, 11, 80)};
    const Camera camera = Camera::perspective({70, -40, 90}, {30, 20, 0}, 60, 240, 320);
    const OverlayTiles listed_tiles = overlay_tiles({box}, camera, 0, camera.rows());
    const std::vector<uint32_t> &tiles = listed_tiles.tiles;
    EXPECT_FALSE(listed_tiles.every_tile);
    EXPECT_EQ(listed_tiles.box_first.size(), tiles.size() + 1);
    EXPECT_EQ(listed_tiles.boxes.size(), tiles.size()); // the one box each
    const int tile_cols = (camera.cols() + 7) / 8, tile_rows = (camera.rows() + 7) / 8;
    std::vector<uint8_t> listed(size_t(tile_cols * tile_rows), 0);
    for (uint32_t t : tiles)
        listed[size_t((t >> 16) * tile_cols + (t & 0xffff))] = 1;
    size_t hit_pixels = 0, missed = 0;
    for (int r = 0; r < camera.rows(); ++r)
        for (int c = 0; c < camera.cols(); ++c) {
            const Ray ray = camera.ray(r, c);
            // slab test of the ray against the box
            double t0 = 0, t1 = INFINITY;
            for (int a = 0; a < 3; ++a) {
                const double lo = (box[0][a] - ray.origin[a]) / ray.direction[a];
                const double hi = (box[1][a] - ray.origin[a]) / ray.direction[a];
                t0 = std::max(t0, std::min(lo, hi));
                t1 = std::min(t1, std::max(lo, hi));
            }
            if (t0 > t1)
                continue;
            ++hit_pixels;
            missed += !listed[size_t((r / 8) * tile_cols + c / 8)];
        }
    EXPECT_GT(hit_pixels, 50u);
    EXPECT_EQ(missed, 0u);
    // the tiles of the box's bounding rectangle (pixel_rects_of)
    const auto rects = pixel_rects_of({box}, camera);
    ASSERT_TRUE(rects && rects->size() == 1);
    const PixelRect &rect = rects->front();
    const size_t rect_tiles = size_t((rect[1] / 8 - rect[0] / 8 + 1) * (rect[3] / 8 - rect[2] / 8 + 1));
    EXPECT_LT(tiles.size(), rect_tiles / 2) << "of " << rect_tiles;
    std::printf("[ tiles ] %zu of the rectangle's %zu\n", tiles.size(), rect_tiles);
    // a band's own tiles: rows from its first
    const std::vector<uint32_t> band = overlay_tiles({box}, camera, 40, 160).tiles;
    EXPECT_FALSE(band.empty());
    for (uint32_t t : band)
        EXPECT_TRUE(listed[size_t(((t >> 16) + 5) * tile_cols + (t & 0xffff))]);
    // a box around the camera: every tile
    const std::array<glm::dvec3, 2> around = {glm::dvec3(60, -50, 80), glm::dvec3(80, -30, 100)};
    const OverlayTiles every = overlay_tiles({box, around}, camera, 0, 16);
    EXPECT_TRUE(every.every_tile);
    EXPECT_EQ(every.tiles.size(), size_t(tile_cols * 2));
    EXPECT_TRUE(every.boxes.empty()); // no lists: every pixel traced
    EXPECT_TRUE(overlay_tiles({}, camera, 0, 16).tiles.empty());
}

TEST(OverlayTiles, ARaysTIsOneFormOfThePointsItPassesForEitherCamera)
{
    // the culling's least t of a box (tile_cull.comp): at a point of any
    // pixel's ray (GpuViewDouble's rays, as the GPU traces them), the form
    // gives that ray's t; from any reference point
    const Model m = geology(40, 56, 30);
    const Tracer t(m, 2.0, Scene{});
    const glm::dvec3 c = t.frame().centre();
    const double r = t.frame().radius();
    const Camera cameras[] = {
        Camera::perspective(c + 2.2 * r * glm::normalize(glm::dvec3(0.4, -0.9, 0.7)), c, 40, 83, 61),
        Camera::orthographic(c + 3.0 * r * glm::normalize(glm::dvec3(0.2, 0.5, 0.8)), c, 1.5 * r,
                             64, 48)};
    for (const Camera &camera : cameras) {
        const GpuViewDouble v = make_gpu_view_double(t, camera);
        const auto vec = [](const double (&a)[4]) { return glm::dvec3(a[0], a[1], a[2]); };
        const glm::dvec3 from =
            t.frame().local_from_exaggerated(camera.origin()) + glm::dvec3(3, -2, 5);
        const glm::dvec4 form = ray_t_form(t, camera, from);
        for (const double x : {-1.0, -0.3, 0.7, 1.0})
            for (const double y : {-1.0, 0.2, 0.9})
                for (const double ray_t : {-40.0, 0.0, 13.5, 200.0}) {
                    const glm::dvec3 p = vec(v.origin) + x * vec(v.spread_u) +
                                         y * vec(v.spread_v) +
                                         ray_t * (vec(v.forward) + x * vec(v.du) + y * vec(v.dv));
                    EXPECT_NEAR(glm::dot(glm::dvec3(form), p - from) + form.w, ray_t, 1e-9 * r)
                        << (camera.parallel() ? "parallel " : "pinhole ") << x << " " << y;
                }
    }
}

TEST(OverlayTiles, ManyBoxesAreListedTileByTileAsEachAlone)
{
    // overlapping boxes, one beside the view and one far off it: each
    // tile lists, in their order, exactly the boxes whose own lists hold it
    const std::vector<std::array<glm::dvec3, 2>> boxes = {
        {glm::dvec3(10, 10, 0), glm::dvec3(11, 11, 80)},
        {glm::dvec3(10.5, 10.2, 0), glm::dvec3(12, 11.5, 60)},
        {glm::dvec3(25, 5, 0), glm::dvec3(27, 9, 40)},
        {glm::dvec3(-400, 30, 0), glm::dvec3(-399, 31, 10)},
        {glm::dvec3(1e7, 1e7, 0), glm::dvec3(1e7 + 1, 1e7 + 1, 10)},
        {glm::dvec3(18, 14, 0), glm::dvec3(30, 15, 5)}};
    const Camera camera = Camera::perspective({70, -40, 90}, {30, 20, 0}, 60, 240, 320);
    for (const auto &[first, rows] : {std::pair{0, 240}, std::pair{37, 101}}) {
        const OverlayTiles all = overlay_tiles(boxes, camera, first, rows);
        ASSERT_FALSE(all.every_tile);
        ASSERT_EQ(all.box_first.size(), all.tiles.size() + 1);
        ASSERT_EQ(all.box_first.back(), all.boxes.size());
        std::map<uint32_t, std::vector<uint32_t>> listed; // tile -> boxes
        for (size_t t = 0; t < all.tiles.size(); ++t) {
            if (t > 0) { // row by row, each tile once
                EXPECT_LT((all.tiles[t - 1] >> 16) * 65536u + (all.tiles[t - 1] & 0xffff),
                          (all.tiles[t] >> 16) * 65536u + (all.tiles[t] & 0xffff));
            }
            ASSERT_LT(all.box_first[t], all.box_first[t + 1]);
            listed[all.tiles[t]].assign(all.boxes.begin() + all.box_first[t],
                                        all.boxes.begin() + all.box_first[t + 1]);
        }
        std::map<uint32_t, std::vector<uint32_t>> alone;
        for (uint32_t b = 0; b < boxes.size(); ++b)
            for (uint32_t t : overlay_tiles({boxes[b]}, camera, first, rows).tiles)
                alone[t].push_back(b);
        EXPECT_EQ(listed, alone) << "rows from " << first;
        EXPECT_FALSE(alone.empty());
        for (const auto &[tile, in] : alone) // the far boxes list nothing
            EXPECT_TRUE(std::find(in.begin(), in.end(), 4u) == in.end());
    }
}

/// Boreholes drilled where the model's stacks are at `cells` (row,
/// column), 1.5 cells wide.
Scene boreholes_at(const Model &m, const std::vector<std::pair<int, int>> &cells)
{
    const Frame &f = m.frame();
    Scene scene;
    for (const auto &[row, col] : cells) {
        Borehole b;
        b.x = f.west + (col + 0.5) * f.ew_res();
        b.y = f.north - (row + 0.5) * f.ns_res();
        b.stack = b.model_stack = m.stack_intervals(m.cell_index(row, col));
        scene.boreholes.push_back(std::move(b));
    }
    scene.borehole_radius = 1.5 * f.ew_res();
    return scene;
}

Scene two_boreholes(const Model &m) { return boreholes_at(m, {{10, 12}, {25, 40}}); }

TEST_P(GpuBands, BoreholesAreShadedAgainOnlyWhereTheirPixelsLie)
{
    const Model m = geology(40, 56, 30);
    const Renderer renderer(m, 2.0, two_boreholes(m), Shading{}, {2, true, 16});
    const Tracer &t = renderer.tracer();
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, options());
    const Camera camera = Camera::perspective(
        t.frame().centre() + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(0.4, -0.9, 0.7)),
        t.frame().centre(), 40, 83, 61);
    const Outputs all{true, true, true};
    Image got = empty_image(camera, all);
    const sbrt_gl::GpuFrameReport r =
        on_gpu.render(camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
    expect_images_agree(renderer.render_image(camera, all), got, 2e-5 * 2 * t.frame().radius(),
                        "two boreholes");
    // bands of 16 rows: 2 tile rows each, 1 for the last 3 rows; 8 tile columns
    EXPECT_EQ(r.gpu.tiles, size_t(8 * (5 * 2 + 1)));
    EXPECT_GT(r.gpu.borehole_tiles, 0u);
    EXPECT_LT(r.gpu.borehole_tiles, r.gpu.tiles / 3);
}

/// The tiles of rows [first, first + rows) of `camera`'s image the GPU's
/// culling (shaders/tile_cull.comp) lists, worked out on the host in
/// double: overlay_tiles' tiles of the boxes' hulls, less each box whose
/// least t (ray_t_form at its corners as make_gpu_boxes rounds them, less
/// the culling's margin) lies beyond the farthest of the tile's model hits
/// (`model_hits`: the model alone, the whole image) with their margin.
size_t tiles_listed_by_depth(const Tracer &tracer, const Camera &camera,
                             const HitImage &model_hits, int first, int rows)
{
    const std::vector<std::array<glm::dvec3, 2>> &boxes = tracer.overlay_boxes();
    const OverlayTiles hulls = overlay_tiles(boxes, camera, first, rows);
    const CoordinateFrame &frame = tracer.frame();
    const glm::dvec3 eye = frame.local_from_exaggerated(camera.origin());
    const glm::dvec4 form = ray_t_form(tracer, camera, eye);
    const auto t_of = [&](glm::dvec3 local) { return glm::dot(glm::dvec3(form), local - eye) + form.w; };
    const std::vector<float> corners = make_gpu_boxes(tracer, boxes);
    std::vector<double> t_box;
    for (size_t b = 0; b < boxes.size(); ++b) {
        double least = INFINITY, scale = 0;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 local(corners[6 * b + ((k & 1) ? 3 : 0)],
                                   corners[6 * b + 1 + ((k & 2) ? 3 : 0)],
                                   corners[6 * b + 2 + ((k & 4) ? 3 : 0)]);
            least = std::min(least, t_of(local));
            const glm::dvec3 v = local - eye;
            scale = std::max(scale, std::abs(form.x * v.x) + std::abs(form.y * v.y) +
                                        std::abs(form.z * v.z) + std::abs(form.w));
        }
        t_box.push_back(least - (1e-5 * scale + 1e-4 * std::abs(least) + 1e-3));
    }
    size_t listed = 0;
    for (size_t k = 0; k < hulls.tiles.size(); ++k) {
        const int tx = int(hulls.tiles[k] & 0xffff), ty = int(hulls.tiles[k] >> 16);
        double far = -INFINITY;
        for (int r = first + 8 * ty; r < std::min(first + 8 * ty + 8, first + rows); ++r)
            for (int c = 8 * tx; c < std::min(8 * tx + 8, camera.cols()); ++c) {
                const Hit &hit = model_hits[size_t(r) * size_t(camera.cols()) + size_t(c)];
                far = std::max(far, hit.is_hit() ? t_of(frame.local_from_exaggerated(
                                                       frame.exaggerated_from_map(hit.point)))
                                                 : INFINITY);
            }
        bool any = false;
        for (uint32_t at = hulls.box_first[k]; at < hulls.box_first[k + 1]; ++at)
            any = any || !(far + 1e-4 * std::abs(far) + 1e-3 < t_box[hulls.boxes[at]]);
        listed += any;
    }
    return listed;
}

TEST_P(GpuBands, TheGpuListsTheTilesTheHostsHullsAndDepthsWould)
{
    // twenty boreholes, from three sides and from nearly above, in bands of
    // 16 rows: the GPU's culling lists the tiles the host finds from the
    // boxes' hulls (overlay_tiles) and the CPU's hits of the model alone
    // (float rounding may move one at a box's edge), fewer than the hulls'
    // where the ground in front hides a box's lower part; the images are
    // the CPU's all the same
    const Model m = geology(40, 56, 30);
    std::vector<std::pair<int, int>> cells;
    for (int k = 0; k < 20; ++k)
        cells.emplace_back(3 + 7 * (k / 5) % 34, 4 + 11 * (k % 5) + k / 5);
    const Renderer renderer(m, 2.0, boreholes_at(m, cells), Shading{}, {2, true, 16});
    const Tracer &t = renderer.tracer();
    const Tracer model_alone(m, 2.0, Scene{});
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, options());
    const Outputs all{true, true, true};
    const glm::dvec3 c = t.frame().centre();
    const double r = t.frame().radius();
    const Camera cameras[] = {
        Camera::perspective(c + 2.2 * r * glm::normalize(glm::dvec3(0.4, -0.9, 0.7)), c, 40, 83, 61),
        Camera::perspective(c + 1.6 * r * glm::normalize(glm::dvec3(-0.8, 0.3, 0.4)), c, 50, 70, 97),
        Camera::orthographic(c + 3.0 * r * glm::normalize(glm::dvec3(0.2, 0.5, 0.8)), c, 1.5 * r,
                             64, 64),
        Camera::perspective(c + glm::dvec3(0.1 * r, 0.05 * r, 2.5 * r), c, 35, 90, 90)};
    const std::vector<std::array<glm::dvec3, 2>> boxes = t.overlay_boxes();
    size_t hulls_total = 0, depths_total = 0;
    for (size_t k = 0; k < std::size(cameras); ++k) {
        const Camera &camera = cameras[k];
        ASSERT_FALSE(overlay_tiles_everywhere(boxes, camera));
        Image got = empty_image(camera, all);
        const sbrt_gl::GpuFrameReport report =
            on_gpu.render(camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
        expect_images_agree(renderer.render_image(camera, all), got, 2e-5 * 2 * r,
                            "view " + std::to_string(k));
        const HitImage model_hits = trace_image(model_alone, camera, 2);
        size_t hulls = 0, depths = 0;
        for (int first = 0; first < camera.rows(); first += 16) {
            const int rows = std::min(16, camera.rows() - first);
            hulls += overlay_tiles(boxes, camera, first, rows).tiles.size();
            depths += tiles_listed_by_depth(t, camera, model_hits, first, rows);
        }
        EXPECT_GT(depths, 0u) << "view " << k;
        EXPECT_LE(size_t(report.gpu.borehole_tiles), depths + depths / 50 + 1) << "view " << k;
        EXPECT_GE(size_t(report.gpu.borehole_tiles) + depths / 50 + 1, depths) << "view " << k;
        std::printf("[ tiles ] view %zu: %zu listed, %zu by the host's depths, the hulls' %zu\n", k,
                    size_t(report.gpu.borehole_tiles), depths, hulls);
        hulls_total += hulls;
        depths_total += depths;
    }
    // the boxes reach down to the model's bottom: from above, the ground
    // in front hides their lower tiles
    EXPECT_LT(depths_total + 10, hulls_total);
}

TEST_P(GpuBands, BandsWhoseEveryTileABoreholeReachesAndRaysOverTheBudget)
{
    // a close-up of a borehole from afar, 12 x 16 pixels: its box reaches
    // every tile of the image (the model pass runs all the same; the
    // boreholes' pass reads this frame's hits, not an earlier frame's);
    // then budgets of 4
    // loop iterations: rays over it in both passes, each listed once
    const Model m = geology(40, 56, 30);
    const Scene scene = two_boreholes(m);
    const Renderer renderer(m, 2.0, scene, Shading{}, {2, true, 4});
    const Tracer &t = renderer.tracer();
    sbrt_gl::GpuRenderer on_gpu(*context_, renderer, options());
    const Borehole &b = scene.boreholes.front();
    const glm::dvec3 axis =
        t.frame().exaggerated_from_map(glm::dvec3(b.x, b.y, t.frame().centre().z));
    const Outputs all{true, true, true};
    const double tolerance = 2e-5 * 2 * t.frame().radius();
    const auto render = [&](const Camera &camera, const std::string &what,
                            sbrt_gl::GpuRenderer *gpu = nullptr) {
        Image got = empty_image(camera, all);
        const sbrt_gl::GpuFrameReport r = (gpu ? *gpu : on_gpu).render(
            camera, all, [&](const Band &band) { gather_band(band, got); }, 2);
        expect_images_agree(renderer.render_image(camera, all), got, tolerance, what);
        EXPECT_LE(r.gpu.over_budget, size_t(camera.rows()) * size_t(camera.cols())) << what;
        return r;
    };
    const Camera far = Camera::perspective(
        t.frame().centre() + 2.2 * t.frame().radius() * glm::normalize(glm::dvec3(0.4, -0.9, 0.7)),
        t.frame().centre(), 40, 61, 83);
    render(far, "far first");
    // the same eye over a larger image first: the hits of its model pass
    // lie where the close-up's boreholes' pass looks
    const glm::dvec3 eye = axis + glm::dvec3(30, -40, 60) * m.frame().ew_res();
    render(Camera::perspective(eye, axis, 30, 61, 83), "close, wide");
    const Camera close = Camera::perspective(eye, axis, 2, 12, 16);
    const sbrt_gl::GpuFrameReport r = render(close, "close-up");
    EXPECT_EQ(r.gpu.borehole_tiles, r.gpu.tiles) << "every tile listed";
    // and the model pass ran for each band all the same: the boreholes'
    // pass reads its hits
    EXPECT_EQ(r.gpu.model_pass_bands, r.gpu.bands);
    sbrt_gl::GpuRenderer budget_4(*context_, renderer, GetParam().options(4));
    EXPECT_GT(render(far, "budget of 4", &budget_4).gpu.over_budget, 0u);
    render(close, "close-up, budget of 4", &budget_4);
}

} // namespace
