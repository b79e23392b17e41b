/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Empty-space skipping: the min-max pyramid against brute force
 *            over its cells, and the tracer with skipping against the same
 *            tracer walking every cell (hidden strata, planes, translucent
 *            strata; best and worst views)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "gpu_compare.hpp"
#include "scene/hidden_materials.hpp"
#include "scene/minmax_pyramid.hpp"
#include "tracing/scene_pruning.hpp"

using namespace sbrt;

namespace {

/// Lowest bottom and highest top of the material in cells [x0, x1) x
/// [y0, y1) (x from the west, y from the south), by brute force.
ZRange brute_range(const Model &m, int x0, int x1, int y0, int y1)
{
    ZRange r;
    const Frame &f = m.frame();
    for (int y = y0; y < std::min(y1, f.rows); ++y)
        for (int x = x0; x < std::min(x1, f.cols); ++x) {
            const uint64_t cell = m.cell_index(f.rows - 1 - y, x);
            float bottom = 0;
            for (uint32_t i = m.stack_begin(cell); i < m.stack_end(cell); ++i) {
                const Interval &iv = m.intervals()[i];
                if (iv.material != EMPTY)
                    r = r.empty() ? ZRange{bottom, iv.top}
                                  : ZRange{std::min(r.low, bottom), std::max(r.high, iv.top)};
                bottom = iv.top;
            }
        }
    return r;
}

/// Every pixel's hit with skipping equals the one walking every cell: same
/// material and face, depth within 1e-9 of the model's size, same veil.
void expect_same_image(const Model &m, Scene scene, const Camera &camera,
                       double zexag = 1)
{
    Scene walk_all = scene;
    walk_all.skip_empty_space = false;
    const Tracer skipping(m, zexag, scene), plain(m, zexag, walk_all);
    ASSERT_GT(skipping.pyramid().levels(), 1);
    ASSERT_EQ(plain.pyramid().levels(), 0);
    const HitImage got = trace_image(skipping, camera, 2);
    const HitImage want = trace_image(plain, camera, 2);
    size_t differ = 0, hits = 0;
    const double tolerance = 1e-9 * 2 * plain.frame().radius();
    for (size_t i = 0; i < want.size(); ++i) {
        hits += want[i].is_hit();
        const bool same = got[i].material == want[i].material &&
                          got[i].face == want[i].face &&
                          (!want[i].is_hit() || std::fabs(got[i].t - want[i].t) < tolerance) &&
                          glm::length(got[i].veil - want[i].veil) < 1e-9 &&
                          std::fabs(got[i].transmittance - want[i].transmittance) < 1e-9;
        differ += !same;
    }
    EXPECT_GT(hits, want.size() / 20);
    EXPECT_EQ(differ, 0u) << "of " << want.size() << " pixels";
}

/// Perspective views of the whole model from azimuth/elevation (degrees).
Camera view(const Model &m, double azimuth, double elevation, double distance = 2.2)
{
    const Tracer t(m, 1.0);
    const double a = glm::radians(azimuth), e = glm::radians(elevation);
    const glm::dvec3 dir(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
    return Camera::perspective(t.frame().centre() + distance * t.frame().radius() * dir, t.frame().centre(), 40,
                               96, 128);
}

} // namespace

TEST(MinMaxPyramid, NodesHoldTheRangeOfTheirCells)
{
    const auto v = sbrt_test::random_voxels(3, 37, 23, 20, 5);
    const Model m = sbrt_test::build_model(v);
    const MinMaxPyramid p(m, [](int, int, ZRange &) {});
    ASSERT_EQ(p.levels(), 7); // 23 x 37 -> 12 x 19 -> ... -> 1 x 1
    for (int level = 0; level < p.levels(); ++level)
        for (int y = 0; y < p.rows(level); ++y)
            for (int x = 0; x < p.cols(level); ++x) {
                const int s = 1 << level;
                const ZRange want = brute_range(m, x * s, (x + 1) * s, y * s, (y + 1) * s);
                const ZRange &got = p.node(level, x, y);
                ASSERT_EQ(got.empty(), want.empty()) << level << " " << x << " " << y;
                if (!want.empty()) {
                    EXPECT_EQ(got.low, want.low);
                    EXPECT_EQ(got.high, want.high);
                }
            }
    EXPECT_EQ(p.bytes(), p.flattened().size() * sizeof(ZRange));
}

TEST(EmptySpaceSkipping, SameImageAsWalkingEveryCell)
{
    const Model m = sbrt_test::geology(60, 90, 40);
    // best (looking down on the surface), oblique, worst (grazing over
    // the top, from below)
    for (double elevation : {80.0, 35.0, 3.0, 0.5, -30.0})
        for (double azimuth : {0.0, 45.0, 200.0})
            expect_same_image(m, {}, view(m, azimuth, elevation));
}

TEST(EmptySpaceSkipping, HiddenStrataPlanesAndTranslucency)
{
    const Model full = sbrt_test::geology(60, 90, 40);
    // hide three strata: the rest floats with gaps under it
    const Model m = hide_materials(full, {1, 3, 5});
    expect_same_image(m, {}, view(m, 30, 20));
    const Tracer t(m, 1.0);
    Scene cut;
    cut.planes = {{t.frame().centre(), {1, 0.3, 0.2}}, {t.frame().centre(), {0, -1, 0.5}}};
    expect_same_image(m, cut, view(m, 60, 25));
    expect_same_image(m, cut, view(m, 250, 10), 3.0);
    Scene veil;
    veil.translucency.extinction.assign(m.materials().size(),
                                        std::numeric_limits<double>::infinity());
    veil.translucency.color.assign(m.materials().size(), glm::dvec3(0.5));
    veil.translucency.extinction[2] = extinction_of(0.3, 25);
    expect_same_image(m, veil, view(m, 120, 15));
}

TEST(EmptySpaceSkipping, BoreholesAreWalkedUpToTheirLogsTops)
{
    // a cell with boreholes is walked up to the highest log there (not the
    // model's top): logs rising above the model, split cylinders whose
    // other half is the model's stack at the axis, low views over the top
    const Model m = sbrt_test::geology(60, 90, 40);
    const Frame &f = m.frame();
    Scene scene;
    for (int k = 0; k < 4; ++k) {
        Borehole b = sbrt_test::borehole_at(m, f.west + (10.5 + 20 * k) * f.ew_res(),
                                            f.south + (12.5 + 11 * k) * f.ns_res());
        b.stack.back().top += float(5 * (k + 1)); // above the model there
        for (Interval &iv : b.stack)
            iv.material = 1 + (iv.material % 3);
        scene.boreholes.push_back(b);
    }
    scene.borehole_radius = 2.5 * f.ew_res();
    const Tracer with(m, 1.0, scene);
    // the cells around a borehole reach its log's top, no higher
    const Frame &frame = m.frame();
    const Borehole &b = scene.boreholes[3];
    const int x = int((b.x - frame.west) / frame.ew_res()), y = int((b.y - frame.south) / frame.ns_res());
    EXPECT_EQ(with.pyramid().node(0, x, y).high, b.stack.back().top);
    EXPECT_LT(with.pyramid().node(0, x, y).high, float(with.frame().top_local()) + 1e-3f);
    for (double elevation : {35.0, 8.0, 1.0})
        for (double azimuth : {20.0, 200.0})
            expect_same_image(m, scene, view(m, azimuth, elevation));
    scene.split = glm::normalize(glm::dvec2(1, -1));
    expect_same_image(m, scene, view(m, 140, 12));
    // a borehole in the hole through the model (cells that hold nothing),
    // its log taken from beside it: seen from above
    const int hole_row = 60 / 3, hole_col = 90 / 4;
    ASSERT_EQ(m.stack_size(m.cell_index(hole_row, hole_col)), 0u);
    Borehole in_hole;
    in_hole.x = f.west + (hole_col + 0.5) * f.ew_res();
    in_hole.y = f.north - (hole_row + 0.5) * f.ns_res();
    in_hole.stack = in_hole.model_stack = m.stack_intervals(m.cell_index(hole_row, hole_col + 4));
    scene = Scene{};
    scene.boreholes = {in_hole};
    scene.borehole_radius = 1.2 * f.ew_res();
    const Tracer t(m, 1.0);
    const glm::dvec3 axis(in_hole.x, in_hole.y, t.frame().centre().z);
    const Camera above = Camera::perspective(axis + glm::dvec3(3, 2, 40) * f.ew_res(), axis, 20,
                                             96, 128);
    expect_same_image(m, scene, above);
    size_t on_cylinder = 0;
    const Tracer drilled(m, 1.0, scene);
    for (int row = 0; row < above.rows(); ++row)
        for (int col = 0; col < above.cols(); ++col)
            on_cylinder += drilled.trace(above.ray(row, col)).face == Face::cylinder;
    EXPECT_GT(on_cylinder, 20u);
}

TEST(EmptySpaceSkipping, CellsCutAwayByAPlaneAreEmpty)
{
    const Model m = sbrt_test::geology(32, 32, 10);
    const Tracer t(m, 1.0);
    Scene cut; // keep the west half: x <= centre
    cut.planes = {{t.frame().centre(), {1, 0, 0}}};
    const Tracer tracer(m, 1.0, cut);
    // columns 17..31 are cut away (16 touches the plane), the rest are
    // empty where the model is
    uint64_t want = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            want += x >= 17 || brute_range(m, x, x + 1, y, y + 1).empty();
    EXPECT_GT(want, 15u * 32u);
    EXPECT_EQ(tracer.pyramid().empty_cells(), want);
}

TEST(ScenePruning, LeavesOutWhatNoRayReachesAndKeepsTheImage)
{
    const Model m = sbrt_test::geology(60, 90, 40);
    const Tracer probe(m, 1.0);
    Scene cut;
    cut.planes = {{probe.frame().centre(), {0, 1, 0}}}; // keep the south half
    const Tracer tracer(m, 1.0, cut);
    // close up on the south-west corner: most cells are out of view
    const glm::dvec3 corner = probe.frame().corner(0);
    const Camera camera = Camera::perspective(
        corner + glm::dvec3(-300, -300, 400), corner + glm::dvec3(200, 200, 0), 30, 96, 128);
    const Pruning p = prune_for_view(tracer, camera);
    EXPECT_GT(p.cut_away.cells, 60u * 90u / 2 - 2 * 90u);
    EXPECT_GT(p.outside_view.cells, 60u * 90u / 4);
    EXPECT_EQ(p.model.intervals().size() + p.cut_away.intervals + p.outside_view.intervals,
              m.intervals().size());
    EXPECT_EQ(p.cut_away.bytes, p.cut_away.intervals * sizeof(CompactInterval)); // as held
    p.model.validate();
    const Tracer pruned(p.model, 1.0, cut);
    const HitImage want = trace_image(tracer, camera, 2);
    const HitImage got = trace_image(pruned, camera, 2);
    size_t differ = 0, hits = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        hits += want[i].is_hit();
        differ += got[i].material != want[i].material || got[i].face != want[i].face ||
                  (want[i].is_hit() && std::fabs(got[i].t - want[i].t) > 1e-6);
    }
    EXPECT_GT(hits, want.size() / 4);
    EXPECT_EQ(differ, 0u);
}

TEST(ScenePruning, BoxesBeyondAnEdgeOrBehindAreOutOfView)
{
    const Camera c = Camera::perspective({0, 0, 0}, {0, 10, 0}, 90, 10, 10);
    EXPECT_FALSE(outside_view(c, {-1, 5, -1}, {1, 6, 1}));  // straight ahead
    EXPECT_TRUE(outside_view(c, {-1, -6, -1}, {1, -5, 1})); // behind
    EXPECT_TRUE(outside_view(c, {20, 5, -1}, {21, 6, 1}));  // far right
    EXPECT_FALSE(outside_view(c, {-1, -1, -1}, {1, 1, 1})); // around the eye
}
