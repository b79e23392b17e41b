/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The coarse first pass (FirstHitBounds): every bound at or
 *            before its pixel's first hit, no hit in a tile said to hold
 *            none, the same hits with and without it, and bounds that
 *            skip most of the walk where rays come down onto the model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "tracing/first_hit_bounds.hpp"
#include "gpu_compare.hpp"
#include "scene/hidden_materials.hpp"

using namespace sbrt;

namespace {

/// Checks the bounds of one camera; returns the mean share of each hit's
/// t that its bound skips (0: none, 1: all of it).
double expect_sound_bounds(const Tracer &tracer, const Camera &camera, int tile,
                           int budget)
{
    const HitImage want = trace_image(tracer, camera, 2, false);
    const FirstHitBounds bounds(tracer, camera, tile, budget, 2);
    EXPECT_EQ(bounds.tiles(), size_t((camera.rows() + tile - 1) / tile) *
                                  size_t((camera.cols() + tile - 1) / tile));
    const double tolerance = 1e-9 * 2 * tracer.frame().radius();
    size_t late = 0, differ = 0, hits = 0;
    double skipped = 0;
    for (int row = 0; row < camera.rows(); ++row)
        for (int col = 0; col < camera.cols(); ++col) {
            const Hit &w = want[size_t(row) * camera.cols() + col];
            const Ray ray = camera.ray(row, col);
            const double t0 = bounds.t_start(row, col, ray);
            if (w.is_hit()) {
                ++hits;
                late += !(t0 <= w.t);
                skipped += w.t > 0 ? std::max(t0, 0.0) / w.t : 1;
            }
            const Hit got = tracer.trace(ray, t0);
            differ += !(got.material == w.material && got.face == w.face &&
                        (!w.is_hit() || (std::fabs(got.t - w.t) < tolerance &&
                                         glm::length(got.normal - w.normal) < 1e-12)) &&
                        glm::length(got.veil - w.veil) < 1e-9);
        }
    EXPECT_EQ(late, 0u) << "bounds past the hit, tile " << tile << " budget " << budget;
    EXPECT_EQ(differ, 0u) << "hits that differ, tile " << tile << " budget " << budget;
    EXPECT_GT(hits, 0u);
    return hits ? skipped / double(hits) : 0;
}

Camera view(const Tracer &t, double azimuth, double elevation, int rows = 72,
            int cols = 96)
{
    const double a = glm::radians(azimuth), e = glm::radians(elevation);
    const glm::dvec3 dir(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
    return Camera::perspective(t.frame().centre() + 2.2 * t.frame().radius() * dir, t.frame().centre(), 40, rows,
                               cols);
}

} // namespace

TEST(FirstPass, BoundsNeverPassTheHitFromAnyCamera)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer tracer(m, 2.0);
    for (double elevation : {80.0, 35.0, 3.0, 0.5, -30.0})
        for (double azimuth : {0.0, 135.0, 250.0})
            for (int tile : {1, 7, 8})
                for (int budget : {1, 32, 100000})
                    expect_sound_bounds(tracer, view(tracer, azimuth, elevation), tile,
                                        budget);
    // parallel rays, and rows of an image traced as an image of their own
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const glm::dvec3 side = c + size * glm::dvec3(0.6, -0.5, 0.4);
    expect_sound_bounds(tracer, Camera::orthographic(side, c, size, 60, 80), 8, 32);
    const Frame &f = m.frame();
    expect_sound_bounds(tracer, Camera::top(f.north, f.south, f.east, f.west, 1e4, 33, 47),
                        8, 32);
    expect_sound_bounds(tracer, view(tracer, 20, 30, 200, 96).rows_window(57, 41), 8, 32);
    // from inside the model's box, in the cave of geology()
    const glm::dvec3 cave(
        f.west + 28 * f.ew_res(), f.north - 24 * f.ns_res(),
        tracer.frame().exaggerated_from_map({0, 0, f.bottom + 10 * f.tb_res()}).z);
    const glm::dvec3 ahead = cave + glm::dvec3(0.2, 1, 0.05);
    expect_sound_bounds(tracer, Camera::perspective(cave, ahead, 90, 40, 60), 8, 32);
}

TEST(FirstPass, HiddenStrataPlanesAndTranslucency)
{
    const Model full = sbrt_test::geology(40, 56, 30);
    const Model m = hide_materials(full, {1, 3, 5}); // floating strata
    const Tracer probe(m, 1.0);
    Scene cut;
    cut.planes = {{probe.frame().centre(), {1, 0.3, 0.2}}, {probe.frame().centre(), {0, -1, 0.5}}};
    const Tracer planes(m, 1.0, cut);
    expect_sound_bounds(planes, view(planes, 60, 25), 8, 32);
    expect_sound_bounds(planes, view(planes, 250, 10), 8, 32);
    Scene veil;
    veil.translucency.extinction.assign(m.materials().size(),
                                        std::numeric_limits<double>::infinity());
    veil.translucency.color.assign(m.materials().size(), glm::dvec3(0.5));
    veil.translucency.extinction[2] = extinction_of(0.3, 25);
    const Tracer translucent(m, 1.0, veil);
    expect_sound_bounds(translucent, view(translucent, 120, 15), 8, 32);
}

TEST(FirstPass, SkipsMostOfTheWalkDownOntoTheModel)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer tracer(m, 2.0);
    // from the top of the model's box, down onto its surface: t = 0 is
    // inside the box, so the share of t skipped is the share of the walk
    const Frame &f = m.frame();
    const glm::dvec3 eye(f.west + 2 * f.ew_res(), f.south + 2 * f.ns_res(),
                         tracer.frame().corner(7).z);
    const Camera down = Camera::perspective(
        eye, tracer.frame().exaggerated_from_map({f.east, f.north, f.bottom}), 30, 60, 80);
    const double skipped = expect_sound_bounds(tracer, down, 8, 32);
    std::printf("[ first pass ] the bounds skip %.1f %% of t to the hits\n", 100 * skipped);
    EXPECT_GT(skipped, 0.8);
    // a view with sky above the model: the tiles up there hold no hit
    const FirstHitBounds sky(tracer, view(tracer, 30, 5), 8, 32);
    EXPECT_GT(sky.empty_tiles(), sky.tiles() / 10);
}

TEST(FirstPass, NoPyramidNoBounds)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    Scene no_skipping;
    no_skipping.skip_empty_space = false;
    const Tracer plain(m, 1.0, no_skipping);
    const Camera camera = view(plain, 30, 40);
    const FirstHitBounds bounds(plain, camera, 8, 32);
    EXPECT_EQ(bounds.tiles(), 0u);
    EXPECT_EQ(bounds.t_start(3, 5, camera.ray(3, 5)), 0.0);
}
