/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Translucent strata, boreholes and fence curtains against
 *            brute force over the source voxels: a fine march along the
 *            ray for Beer-Lambert, the class of the voxel at each hit
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "scene/overlay_geometry.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

/// Class of the voxel holding real map point p, NULL_CLASS outside.
int32_t voxel_class(const sbrt_test::Voxels &v, glm::dvec3 p)
{
    const Frame &f = v.frame;
    const int col = int(std::floor((p.x - f.west) / f.ew_res()));
    const int row = int(std::floor((f.north - p.y) / f.ns_res()));
    const int depth = int(std::floor((p.z - f.bottom) / f.tb_res()));
    if (col < 0 || col >= f.cols || row < 0 || row >= f.rows || depth < 0 ||
        depth >= f.depths)
        return NULL_CLASS;
    return v.classes[(size_t(depth) * f.rows + row) * f.cols + col];
}

uint32_t index_of(const Model &m, int32_t id)
{
    const int64_t k = m.find_material(id);
    EXPECT_GT(k, 0) << id;
    return uint32_t(k);
}

/// Classes `ids` translucent (alpha over `length`), the rest opaque.
Translucency translucent(const Model &m, const std::vector<int32_t> &ids,
                         double alpha, double length)
{
    Translucency tr;
    tr.length = length;
    tr.extinction.assign(m.materials().size(), std::numeric_limits<double>::infinity());
    tr.color.assign(m.materials().size(), glm::dvec3(0));
    for (size_t k = 0; k < ids.size(); ++k) {
        const uint32_t i = index_of(m, ids[k]);
        tr.extinction[i] = extinction_of(alpha, length);
        tr.color[i] = glm::dvec3(0.2 + 0.3 * k, 0.9 - 0.2 * k, 0.5);
    }
    return tr;
}

/// Brute force: march the ray in steps of `step` map units through the
/// voxels, absorbing in the translucent classes, stopping at an opaque one.
Hit march(const sbrt_test::Voxels &v, const Model &m, const Translucency &tr,
          const Tracer &tracer, const Ray &ray, double t_end, double step)
{
    Hit hit;
    glm::dvec3 veil(0); // accumulated in double, stored as the tracer stores it
    double transmittance = 1;
    for (double t = step / 2; t < t_end; t += step) {
        const int32_t id =
            voxel_class(v, tracer.frame().map_from_exaggerated(ray.origin + t * ray.direction));
        if (id == NULL_CLASS)
            continue;
        const uint32_t k = uint32_t(m.find_material(id));
        if (tr.opaque(k)) {
            hit.material = k;
            hit.t = t;
            break;
        }
        const double keep = std::exp(-tr.extinction[k] * step);
        veil += transmittance * (1 - keep) * tr.color[k];
        transmittance *= keep;
    }
    hit.veil = veil;
    hit.transmittance = float(transmittance);
    return hit;
}


} // namespace

TEST(Translucency, VerticalRaysAbsorbTheStrataThicknessExactly)
{
    const auto v = sbrt_test::random_voxels(21, 9, 11, 40, 5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const double zexag = 3;
    const Translucency tr = translucent(m, {-13, 1}, 0.3, 7.5);
    const Tracer tracer(m, zexag, Scene{{}, tr, {}, 0, {}, {}, true});
    const HitImage hits = trace_image(tracer, sbrt_test::top_camera(f, 1e4), 2);
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            // voxel by voxel from the top: each translucent voxel is tb_res
            // * zexag long for a vertical ray
            Hit want;
            glm::dvec3 veil(0);
            double transmittance = 1;
            for (int z = f.depths - 1; z >= 0 && !want.is_hit(); --z) {
                const int32_t id = v.classes[(size_t(z) * f.rows + row) * f.cols + col];
                if (id == NULL_CLASS)
                    continue;
                const uint32_t k = uint32_t(m.find_material(id));
                if (tr.opaque(k)) {
                    want.material = k;
                    continue;
                }
                const double keep = std::exp(-tr.extinction[k] * f.tb_res() * zexag);
                veil += transmittance * (1 - keep) * tr.color[k];
                transmittance *= keep;
            }
            // the hit keeps its shading terms in single precision
            const Hit &got = hits[size_t(row) * f.cols + col];
            ASSERT_EQ(got.material, want.material) << row << "," << col;
            ASSERT_NEAR(got.transmittance, transmittance, 1e-6);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got.veil[c], veil[c], 1e-6);
        }
}

TEST(Translucency, ObliqueRaysMatchAFineMarch)
{
    const auto v = sbrt_test::random_voxels(4, 12, 10, 30, 4);
    const Model m = sbrt_test::build_model(v);
    const Translucency tr = translucent(m, {-13, 1, 8}, 0.25, 5.0);
    const double zexag = 2;
    const Tracer tracer(m, zexag, Scene{{}, tr, {}, 0, {}, {}, true});
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const Camera cam = Camera::perspective(c + size * glm::dvec3(0.7, -0.9, 0.6), c,
                                           40, 12, 16);
    const double step = 0.002;
    size_t compared = 0, translucent_rays = 0;
    for (int row = 0; row < cam.rows(); ++row)
        for (int col = 0; col < cam.cols(); ++col) {
            const Ray ray = cam.ray(row, col);
            const Hit got = tracer.trace(ray);
            const double t_end = got.is_hit() ? got.t : 3 * size;
            const Hit want = march(v, m, tr, tracer, ray, t_end, step);
            translucent_rays += got.transmittance < 0.999;
            // the march ends a step early or late at an opaque voxel's wall:
            // compare what lies in front of the exact hit
            EXPECT_NEAR(got.transmittance, want.transmittance, 0.01)
                << row << "," << col;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(got.veil[k], want.veil[k], 0.01) << row << "," << col;
            ++compared;
        }
    EXPECT_EQ(compared, size_t(cam.rows() * cam.cols()));
    EXPECT_GT(translucent_rays, compared / 4);
}

TEST(Translucency, SplittingAStratumDoesNotChangeTheResult)
{
    // one translucent column split into many intervals of the same class
    // by cells: a horizontal ray crossing 20 cells of it keeps exactly
    // exp(-extinction * 20 cells)
    sbrt_test::Voxels v;
    v.frame.rows = 1;
    v.frame.cols = 20;
    v.frame.depths = 4;
    v.frame.west = 0;
    v.frame.east = 20 * 3.0;
    v.frame.south = 0;
    v.frame.north = 3;
    v.frame.bottom = 0;
    v.frame.top = 4;
    v.classes.assign(v.frame.voxels(), 5);
    const Model m = sbrt_test::build_model(v);
    const Translucency tr = translucent(m, {5}, 0.1, 3.0);
    const Tracer tracer(m, 1.0, Scene{{}, tr, {}, 0, {}, {}, true});
    const Hit hit = tracer.trace({{-10, 1.3, 2.2}, {1, 0, 0}});
    EXPECT_FALSE(hit.is_hit());
    EXPECT_NEAR(hit.transmittance, std::pow(0.9, 20), 1e-6);
}

TEST(Boreholes, CylinderShowsTheStackAtItsPoint)
{
    const auto v = sbrt_test::random_voxels(8, 10, 12, 30, 6);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const Borehole b =
        sbrt_test::borehole_at(m, f.west + 6.3 * f.ew_res(), f.south + 4.6 * f.ns_res());
    const int row = f.rows - 1 - 4, col = 6;
    const double r = 1.7;
    Scene scene;
    scene.boreholes = {b};
    scene.borehole_radius = r;
    scene.draw_model = false;
    const Tracer tracer(m, 1.0, scene);
    EXPECT_TRUE(tracer.has_overlays());
    size_t solid = 0;
    for (int depth = 0; depth < f.depths; ++depth) {
        // a horizontal ray from the west at the voxel's mid-height, 0.6 r
        // north of the axis
        const double z = f.bottom + (depth + 0.5) * f.tb_res();
        const double dy = 0.6 * r;
        const Hit hit = tracer.trace({{f.west - 50, b.y + dy, z}, {1, 0, 0}});
        const int32_t want = v.classes[(size_t(depth) * f.rows + row) * f.cols + col];
        if (want == NULL_CLASS) {
            EXPECT_FALSE(hit.is_hit()) << depth;
            continue;
        }
        ++solid;
        ASSERT_TRUE(hit.is_hit()) << depth;
        EXPECT_EQ(m.materials()[hit.material].id, want) << depth;
        EXPECT_EQ(hit.face, Face::cylinder);
        const double x_in = b.x - std::sqrt(r * r - dy * dy);
        EXPECT_NEAR(hit.point.x, x_in, 1e-9);
        EXPECT_NEAR(hit.normal.x, -std::sqrt(1 - 0.36), 1e-6);
        EXPECT_NEAR(hit.normal.y, 0.6, 1e-6);
    }
    EXPECT_GT(solid, 5u);
    // a ray passing beside the cylinder meets nothing: the model is not drawn
    EXPECT_FALSE(tracer.trace({{f.west - 50, b.y + 1.01 * r, f.bottom + 1}, {1, 0, 0}}).is_hit());
}

TEST(Boreholes, SplitCylinderShowsTheLogOnOneHalf)
{
    const auto v = sbrt_test::random_voxels(3, 6, 6, 20, 4);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    Borehole b;
    b.x = f.west + 2.5 * f.ew_res();
    b.y = f.south + 2.5 * f.ns_res();
    // the log: material 1 below local z 10, material 2 above up to 20
    b.stack = {{1, 10.0f}, {2, 20.0f}};
    b.model_stack = {{3, 20.0f}};
    Scene scene;
    scene.boreholes = {b};
    scene.borehole_radius = 2;
    scene.split = glm::dvec2(0, 1); // the log on the north half
    scene.draw_model = false;
    const Tracer tracer(m, 1.0, scene);
    const double low = f.bottom + 5 * f.tb_res(), high = f.bottom + 15 * f.tb_res();
    EXPECT_EQ(tracer.trace({{f.west - 9, b.y + 1, low}, {1, 0, 0}}).material, 1u);
    EXPECT_EQ(tracer.trace({{f.west - 9, b.y + 1, high}, {1, 0, 0}}).material, 2u);
    EXPECT_EQ(tracer.trace({{f.west - 9, b.y - 1, low}, {1, 0, 0}}).material, 3u);
    // from the south the ray meets the model half first
    const Hit h = tracer.trace({{b.x + 0.5, f.south - 9, high}, {0, 1, 0}});
    EXPECT_EQ(h.material, 3u);
    EXPECT_EQ(h.face, Face::cylinder);
}

TEST(Boreholes, InsideTheDrawnModelTheyChangeNoMaterial)
{
    // with the model drawn, a cylinder showing the model's own stack is
    // invisible in the material map of a top view
    const auto v = sbrt_test::random_voxels(12, 14, 14, 20, 5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    Scene scene;
    scene.borehole_radius = 0.4 * f.ew_res();
    for (int k = 0; k < 5; ++k)
        scene.boreholes.push_back(sbrt_test::borehole_at(m, f.west + (2.5 + 2 * k) * f.ew_res(),
                                              f.south + (3.5 + k) * f.ns_res()));
    const Tracer plain(m, 1.0), with(m, 1.0, scene);
    const Camera cam = sbrt_test::top_camera(f, 1e3);
    const auto a = trace_image(plain, cam, 2), b = trace_image(with, cam, 2);
    for (size_t i = 0; i < a.size(); ++i)
        ASSERT_EQ(a[i].material, b[i].material) << i;
}

TEST(Fence, CurtainShowsTheClassAtEachPoint)
{
    const auto v = sbrt_test::random_voxels(30, 16, 16, 24, 6);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    Scene scene;
    // a diagonal panel from the south-west to the north-east
    const glm::dvec2 a(f.west + 1.3 * f.ew_res(), f.south + 2.2 * f.ns_res());
    const glm::dvec2 b(f.west + 13.1 * f.ew_res(), f.south + 12.7 * f.ns_res());
    scene.fence = {{a, b}};
    scene.draw_model = false;
    const double zexag = 2;
    const Tracer tracer(m, zexag, scene);
    const glm::dvec2 along = b - a;
    const glm::dvec2 normal = glm::normalize(glm::dvec2(-along.y, along.x));
    size_t solid = 0, holes = 0;
    for (double u = 0.013; u < 1; u += 0.047)
        for (int depth = 0; depth < f.depths; ++depth) {
            const glm::dvec2 p = a + u * along;
            const double z = f.bottom + (depth + 0.3) * f.tb_res();
            // from the curtain's north-west side, slanting down a little
            const glm::dvec3 target(p, f.bottom + (z - f.bottom) * zexag);
            const glm::dvec3 dir = glm::normalize(glm::dvec3(-normal, -0.05));
            const Hit hit = tracer.trace({target - 200.0 * dir, dir});
            const int32_t want = voxel_class(v, tracer.frame().map_from_exaggerated(target));
            if (want == NULL_CLASS) {
                // the ray may still hit the curtain lower down; never here
                EXPECT_TRUE(!hit.is_hit() || hit.t > 200 + 1e-9);
                ++holes;
                continue;
            }
            ++solid;
            ASSERT_TRUE(hit.is_hit());
            EXPECT_EQ(m.materials()[hit.material].id, want);
            EXPECT_EQ(hit.face, Face::fence);
            EXPECT_NEAR(hit.t, 200, 1e-8);
            // turned towards the ray's origin, on the +normal side
            EXPECT_NEAR(glm::dot(glm::dvec3(hit.normal), glm::dvec3(normal, 0)), 1, 1e-6);
        }
    EXPECT_GT(solid, 100u);
    EXPECT_GT(holes, 10u);
}

TEST(Boreholes, ManyBoreholesWalkTheCells)
{
    // more boreholes than are met directly: the rays walk the cells (and
    // the box of the cells with boreholes); one borehole per cell centre
    const auto v = sbrt_test::random_voxels(17, 20, 22, 16, 6);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    Scene scene;
    scene.borehole_radius = 0.4 * std::min(f.ew_res(), f.ns_res());
    scene.draw_model = false;
    for (int row = 1; row < f.rows - 1; ++row) // not the outer ring
        for (int col = 1; col < f.cols - 1; ++col)
            scene.boreholes.push_back(sbrt_test::borehole_at(m, f.west + (col + 0.5) * f.ew_res(),
                                                  f.north - (row + 0.5) * f.ns_res()));
    ASSERT_GT(scene.boreholes.size(), 256u);
    const Tracer plain(m, 1.0), cylinders(m, 1.0, scene);
    const Camera cam = sbrt_test::top_camera(f, 1e3);
    const auto want = trace_image(plain, cam, 2), got = trace_image(cylinders, cam, 2);
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            const size_t i = size_t(row) * f.cols + col;
            const bool ring = row == 0 || col == 0 || row == f.rows - 1 || col == f.cols - 1;
            ASSERT_EQ(got[i].material, ring ? EMPTY : want[i].material) << row << "," << col;
        }
}

TEST(Overlays, ImagesTraceOnlyWhereTheOverlaysProject)
{
    // without the model only the pixels the overlays' boxes cover are
    // traced: the image equals tracing every pixel, from any camera
    const auto v = sbrt_test::random_voxels(23, 16, 14, 20, 5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = m.frame();
    Scene scene;
    scene.borehole_radius = 0.4 * f.ew_res();
    scene.boreholes = {sbrt_test::borehole_at(m, f.west + 3.5 * f.ew_res(), f.south + 4.5 * f.ns_res()),
                       sbrt_test::borehole_at(m, f.west + 10.2 * f.ew_res(), f.south + 11.7 * f.ns_res())};
    scene.fence = {{{f.west + 2 * f.ew_res(), f.north - 2 * f.ns_res()},
                    {f.west + 9 * f.ew_res(), f.north - 5 * f.ns_res()}}};
    scene.draw_model = false;
    const Tracer tracer(m, 2.0, scene);
    ASSERT_EQ(tracer.overlay_bounds().size(), 3u);
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    size_t hits = 0;
    for (const Camera &cam :
         {Camera::perspective(c + glm::dvec3(0.6, -0.8, 0.5) * size, c, 40, 60, 80),
          Camera::orthographic(c + glm::dvec3(-0.7, 0.5, 0.3) * size, c, size, 60, 80),
          Camera::perspective(c + glm::dvec3(0.01, 0.02, 0.01) * size, c + glm::dvec3(1, 0, 0),
                              70, 30, 40), // among the overlays
          sbrt_test::top_camera(f, 1e3)}) {
        const auto image = trace_image(tracer, cam, 2);
        for (int row = 0; row < cam.rows(); ++row)
            for (int col = 0; col < cam.cols(); ++col) {
                const Hit want = tracer.trace(cam.ray(row, col));
                const Hit &got = image[size_t(row) * cam.cols() + col];
                ASSERT_EQ(got.material, want.material) << row << "," << col;
                hits += got.is_hit();
            }
    }
    EXPECT_GT(hits, 100u);
}

TEST(Fence, SegmentsFarOutsideTheFrameAreClippedNotOverflowed)
{
    // regression (issue 15): a fence vertex at 1e10 map units made
    // cells_near_segment convert 1e10 to int (undefined behaviour)
    const auto v = sbrt_test::random_voxels(31, 12, 15, 16, 5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const double y = f.south + 6.4 * f.ns_res();
    EXPECT_TRUE(cells_near_segment(f, {-1e10, f.north + 1e9}, {1e10, f.north + 1e9}, 0)
                    .empty());
    const auto far = cells_near_segment(f, {-1e10, y}, {1e10, y}, 0);
    const auto near = cells_near_segment(f, {f.west - 1, y}, {f.east + 1, y}, 0);
    EXPECT_EQ(far, near);
    EXPECT_GE(far.size(), size_t(f.cols));
    // a margin wider than the frame: every cell is a candidate
    EXPECT_EQ(cells_near_segment(f, {f.west, y}, {f.west, y}, 1e12).size(), f.cells());
    // the same curtain drawn from both: the same hits
    Scene far_scene, near_scene;
    far_scene.fence = {{{-1e10, y}, {1e10, y}}};
    near_scene.fence = {{{f.west - 1e3, y}, {f.east + 1e3, y}}};
    far_scene.draw_model = near_scene.draw_model = false;
    const Tracer a(m, 1.0, far_scene), b(m, 1.0, near_scene);
    const glm::dvec3 c = a.frame().centre();
    const Camera cam = Camera::perspective(c + glm::dvec3(30, -200, 80), c, 50, 30, 40);
    const auto ha = trace_image(a, cam, 2), hb = trace_image(b, cam, 2);
    size_t hits = 0;
    for (size_t i = 0; i < ha.size(); ++i) {
        ASSERT_EQ(ha[i].material, hb[i].material) << i;
        hits += ha[i].is_hit();
    }
    EXPECT_GT(hits, 0u);
}

TEST(Overlays, PixelRectanglesSkipBoxesBehindTheCamera)
{
    // boxes wholly behind a perspective camera reach no pixel; a box the
    // camera is in (or that reaches behind it) may reach any pixel
    const Camera camera = Camera::perspective({0, 0, 0}, {1, 0, 0}, 60, 30, 40);
    const std::array<glm::dvec3, 2> ahead{glm::dvec3(10, -1, -1), glm::dvec3(12, 1, 1)};
    const std::array<glm::dvec3, 2> behind{glm::dvec3(-12, -1, -1), glm::dvec3(-10, 1, 1)};
    const std::array<glm::dvec3, 2> around{glm::dvec3(-1, -1, -1), glm::dvec3(1, 1, 1)};
    const auto both = pixel_rects_of({ahead, behind}, camera);
    ASSERT_TRUE(both);
    ASSERT_EQ(both->size(), 1u);
    const PixelRect rect = (*both)[0];
    EXPECT_LT(rect[0], 15); // around the image's centre
    EXPECT_GT(rect[1], 15);
    EXPECT_LT(rect[2], 20);
    EXPECT_GT(rect[3], 20);
    const auto only_behind = pixel_rects_of({behind}, camera);
    ASSERT_TRUE(only_behind);
    EXPECT_TRUE(only_behind->empty());
    EXPECT_FALSE(pixel_rects_of({ahead, around}, camera));
    // the spans of a row merge overlapping and touching rectangles
    const std::vector<PixelRect> rects{{0, 5, 2, 4}, {3, 9, 5, 8}, {1, 2, 12, 13}};
    EXPECT_EQ(row_spans(rects, 4), (std::vector<std::pair<int, int>>{{2, 8}}));
    EXPECT_EQ(row_spans(rects, 2), (std::vector<std::pair<int, int>>{{2, 4}, {12, 13}}));
    EXPECT_TRUE(row_spans(rects, 11).empty());
}
