/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Scene pruning without a tracer: the stacks it leaves out are
 *            those a tracer's pyramid holds as empty or out of view (planes
 *            at a slant, hidden strata, boreholes and a fence)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <gtest/gtest.h>

#include "gpu_compare.hpp"
#include "scene/hidden_materials.hpp"
#include "test_support.hpp"
#include "tracing/scene_pruning.hpp"

using namespace sbrt;

namespace {

void expect_same_pruning(const Model &m, double zexag, const Scene &scene,
                         const Camera &camera)
{
    const Tracer tracer(m, zexag, scene);
    const Pruning want = prune_for_view(tracer, camera);
    const Pruning got = prune_for_view(m, zexag, scene, camera);
    EXPECT_EQ(got.cut_away.cells, want.cut_away.cells);
    EXPECT_EQ(got.cut_away.intervals, want.cut_away.intervals);
    EXPECT_EQ(got.outside_view.cells, want.outside_view.cells);
    EXPECT_EQ(got.outside_view.bytes, want.outside_view.bytes);
    const Frame &f = m.frame();
    ASSERT_EQ(got.model.intervals().size(), want.model.intervals().size());
    for (uint64_t cell = 0; cell < f.cells(); ++cell) {
        const std::vector<Interval> a = got.model.stack_intervals(cell),
                                    b = want.model.stack_intervals(cell);
        ASSERT_EQ(a.size(), b.size()) << "cell " << cell;
        for (size_t k = 0; k < a.size(); ++k) {
            EXPECT_EQ(a[k].top, b[k].top) << "cell " << cell;
            EXPECT_EQ(a[k].material, b[k].material) << "cell " << cell;
        }
    }
}

} // namespace

TEST(ScenePruningWithoutTracer, LeavesOutWhatTheTracersPyramidDoes)
{
    const Model full = sbrt_test::geology(40, 56, 24);
    const Model m = hide_materials(full, {1, 3, 5}); // floating strata
    const CoordinateFrame frame = CoordinateFrame::of(m, 2.5);
    const Frame &f = m.frame();
    Scene scene;
    // two slanted planes that cut the north-east away
    scene.planes = {{frame.map_from_exaggerated(frame.centre()), {1, 1, 0.4}},
                    {frame.map_from_exaggerated(frame.centre()), {0.2, 1, -0.3}}};
    scene.borehole_radius = 1.5 * f.ew_res();
    scene.boreholes = {sbrt_test::borehole_at(m, f.east - 3.5 * f.ew_res(),
                                              f.north - 4.5 * f.ns_res())};
    scene.fence = {{{f.west + 30 * f.ew_res(), f.north - 2 * f.ns_res()},
                    {f.east - 2 * f.ew_res(), f.south + 20 * f.ns_res()}}};
    const glm::dvec3 corner = frame.corner(0);
    const Camera camera = Camera::perspective(corner + glm::dvec3(-300, -300, 500),
                                              frame.centre(), 35, 80, 96);
    const Pruning p = prune_for_view(m, 2.5, scene, camera);
    // the scene prunes both ways, and keeps the overlays' cells
    EXPECT_GT(p.cut_away.cells, 200u);
    EXPECT_GT(p.outside_view.cells, 10u);
    expect_same_pruning(m, 2.5, scene, camera);
    // and without overlays, without planes, without skipping
    Scene planes_only = scene;
    planes_only.boreholes.clear();
    planes_only.fence.clear();
    expect_same_pruning(m, 2.5, planes_only, camera);
    expect_same_pruning(m, 2.5, Scene(), camera);
    Scene walk_all = scene;
    walk_all.skip_empty_space = false;
    expect_same_pruning(m, 2.5, walk_all, camera);
}
