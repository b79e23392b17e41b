/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Sequences of views: the orbit's turn, keyframes (parsing,
 *            passing through every key), even spacing along a line, the
 *            sweep's plane, the model's top under a point
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera_path.hpp"
#include "renderer.hpp"
#include "util/error.hpp"
#include "gpu_compare.hpp"

using namespace sbrt;

TEST(CameraPath, TurnIsCounterClockwiseSeenFromAbove)
{
    // east of the axis, a quarter turn: north of it
    const glm::dvec3 p = turn_about_vertical({110, 50, 7}, {100, 50, 0}, 90);
    EXPECT_NEAR(p.x, 100, 1e-12);
    EXPECT_NEAR(p.y, 60, 1e-12);
    EXPECT_EQ(p.z, 7);
}

TEST(CameraPath, OrbitKeepsDistanceAndTurns)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 2.0);
    View v;
    v.position = glm::dvec3(-500, -400, 900);
    v.target = glm::dvec3(300, 350, 100);
    const std::vector<Camera> cams = orbit_cameras(v, t.model(), t.frame(), 30, 40, 4, 360);
    ASSERT_EQ(cams.size(), 4u);
    const glm::dvec3 target = t.frame().exaggerated_from_map(*v.target);
    const glm::dvec3 first = t.frame().exaggerated_from_map(*v.position);
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(glm::length(cams[size_t(k)].origin() - target),
                    glm::length(first - target), 1e-9);
        const glm::dvec3 want = turn_about_vertical(first, target, 90.0 * k);
        EXPECT_LT(glm::length(cams[size_t(k)].origin() - want), 1e-9) << k;
    }
    v.kind = ViewKind::top;
    EXPECT_THROW(orbit_cameras(v, t.model(), t.frame(), 30, 40, 4, 360), Error);
}

TEST(CameraPath, KeyframesAreParsedAndPassedThrough)
{
    const std::vector<Keyframe> keys = parse_keyframes(
        "# x y z tx ty tz fov\n0 0 100 10 10 0\n\n100,0,200, 10,10,0, 30 # second\n"
        "100 100 100 10 10 0 50\n",
        40);
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[0].fov, 40);
    EXPECT_EQ(keys[1].position, glm::dvec3(100, 0, 200));
    // 5 frames through 3 keys: frames 1, 3 and 5 are the keys exactly
    for (int k : {1, 3, 5}) {
        const Keyframe at = keyframe_at(keys, k, 5);
        const Keyframe &want = keys[size_t((k - 1) / 2)];
        EXPECT_EQ(at.position, want.position) << k;
        EXPECT_EQ(at.target, want.target) << k;
        EXPECT_EQ(at.fov, want.fov) << k;
    }
    // between keys: between them, and the field of view linear
    const Keyframe mid = keyframe_at(keys, 2, 5);
    EXPECT_GT(mid.position.x, 0);
    EXPECT_LT(mid.position.x, 100);
    EXPECT_DOUBLE_EQ(mid.fov, 35);
    for (const char *bad : {"0 0 100 10 10 0\n", "", "0 0 100 10 10\n1 2 3 4 5 6\n",
                            "0 0 1 0 0 1\n1 1 1 2 2 2\n", "0 0 x 1 1 1\n1 1 1 2 2 2\n",
                            "0 0 1 1 1 1 200\n1 1 1 2 2 2\n"})
        EXPECT_THROW(parse_keyframes(bad, 40), Error) << bad;
}

TEST(CameraPath, FramesAreEvenlySpacedAlongTheLine)
{
    // an L: 300 east, then 100 north, the corner doubled
    const std::vector<glm::dvec3> line = {{0, 0, 10}, {300, 0, 40}, {300, 0, 40},
                                          {300, 100, 50}};
    glm::dvec3 p, d;
    along_line(line, 1, 5, p, d);
    EXPECT_EQ(p, glm::dvec3(0, 0, 10));
    EXPECT_EQ(d, glm::dvec3(1, 0, 0));
    along_line(line, 2, 5, p, d); // 100 along
    EXPECT_NEAR(p.x, 100, 1e-9);
    EXPECT_NEAR(p.z, 20, 1e-9);
    along_line(line, 4, 5, p, d); // 300 along: the corner
    EXPECT_NEAR(p.x, 300, 1e-9);
    along_line(line, 5, 5, p, d);
    EXPECT_LT(glm::length(p - glm::dvec3(300, 100, 50)), 1e-9);
    EXPECT_EQ(d, glm::dvec3(0, 1, 0));
    EXPECT_THROW(along_line({{1, 1, 1}, {1, 1, 5}}, 1, 2, p, d), Error);
}

TEST(CameraPath, SweepStartsOutsideAndCutsEvenly)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 1.0);
    const ClipPlane up{{0, 0, 0}, {0, 0, 2}};
    const double top = t.frame().top_elevation(), bottom = m.frame().bottom;
    for (int k = 1; k <= 4; ++k) {
        const ClipPlane p = swept_plane(up, t.frame(), k, 4);
        EXPECT_EQ(p.normal, up.normal);
        EXPECT_NEAR(p.point.z, top - (top - bottom) * (k - 1) / 4, 1e-9) << k;
    }
    EXPECT_THROW(swept_plane(up, t.frame(), 5, 4), Error);
}

TEST(CameraPath, SurfaceElevationIsTheStackTop)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 3.0);
    const Frame &f = m.frame();
    for (int row : {0, 7, 19})
        for (int col : {0, 11, 23}) {
            const uint64_t cell = m.cell_index(row, col);
            if (!m.stack_size(cell))
                continue;
            const double want =
                f.bottom + double(m.intervals()[m.stack_end(cell) - 1].top) * f.tb_res();
            EXPECT_NEAR(surface_elevation(t.model(), t.frame(), f.west + (col + 0.5) * f.ew_res(),
                                          f.north - (row + 0.5) * f.ns_res()),
                        want, 1e-9);
        }
    EXPECT_EQ(surface_elevation(t.model(), t.frame(), f.west - 1, f.north + 1), t.frame().top_elevation());
}

TEST(CameraWindow, TilesHaveTheWholeImagesRaysAndPixels)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 2.0);
    View v;
    v.azimuth = 200;
    const int rows = 30, cols = 44;
    for (const ViewKind kind : {ViewKind::perspective, ViewKind::orthographic}) {
        v.kind = kind;
        const Camera whole = view_camera(v, t.model(), t.frame(), rows, cols);
        const Camera tile = whole.window(7, 13, 20, 17);
        EXPECT_TRUE(tile.is_window());
        EXPECT_FALSE(whole.is_window());
        for (int r = 0; r < 13; ++r)
            for (int c = 0; c < 17; ++c) {
                const Ray a = whole.ray(7 + r, 20 + c), b = tile.ray(r, c);
                ASSERT_EQ(a.origin, b.origin);
                ASSERT_EQ(a.direction, b.direction);
            }
        // a tile of a band is the same tile
        const Camera band = whole.rows_window(5, 20).window(2, 13, 20, 17);
        EXPECT_EQ(band.ray(3, 4).direction, tile.ray(3, 4).direction);
        // the linear forms agree with the rays
        glm::dvec3 o, f, du, dv;
        tile.linear_rays(o, f, du, dv);
        const glm::dvec2 p = tile.pixel_ndc(5, 9);
        const glm::dvec3 d = kind == ViewKind::perspective
                                 ? glm::normalize(f + p.x * du + p.y * dv)
                                 : f;
        EXPECT_LT(glm::length(d - tile.ray(5, 9).direction), 1e-12);
        // and project() gives back a pixel's own coordinates
        double x, y;
        ASSERT_TRUE(tile.project(tile.ray(5, 9).origin + 100.0 * tile.ray(5, 9).direction, x, y));
        EXPECT_NEAR(x, p.x, 1e-9);
        EXPECT_NEAR(y, p.y, 1e-9);
        // rendered: the tile's pixels are the whole image's
        Scene scene;
        const Renderer renderer(m, 2.0, scene, Shading{});
        const Outputs outputs{true, false, true};
        const Image all = renderer.render_image(whole, outputs);
        const Image part = renderer.render_image(tile, outputs);
        for (int r = 0; r < 13; ++r)
            for (int c = 0; c < 17; ++c) {
                const size_t i = size_t(7 + r) * cols + size_t(20 + c), j = size_t(r) * 17 + c;
                ASSERT_EQ(all.material[i], part.material[j]) << r << " " << c;
                const double a = all.depth[i], b = part.depth[j];
                ASSERT_TRUE((std::isnan(a) && std::isnan(b)) || a == b) << r << " " << c;
                for (int k = 0; k < 3; ++k)
                    ASSERT_EQ(all.rgb[3 * i + k], part.rgb[3 * j + k]);
            }
    }
    const Camera whole = view_camera(v, t.model(), t.frame(), rows, cols);
    EXPECT_THROW(whole.window(20, 11, 0, 5), Error);
    EXPECT_THROW(whole.window(0, 5, 40, 5), Error);
}

TEST(CameraPath, PathKindsFromTheirWords)
{
    for (PathKind kind : {PathKind::orbit, PathKind::line, PathKind::keys, PathKind::sweep})
        EXPECT_EQ(parse_path_kind(path_kind_name(kind)), kind);
    EXPECT_EQ(std::string(path_kind_name(PathKind::sweep)), "sweep");
    EXPECT_THROW(parse_path_kind("spiral"), Error);
    EXPECT_THROW(parse_path_kind(""), Error);
}
