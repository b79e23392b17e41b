/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Scene operations against brute force over the source voxels:
 *            hidden materials (the subcrop map; hidden while tracing as
 *            removed from the model, hit for hit) and clip planes (a
 *            horizontal cut is a slice of the voxels)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <set>

#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "scene/hidden_materials.hpp"
#include "scene/view.hpp"
#include "shading/shading.hpp"
#include "model/material_table.hpp"
#include "gpu_compare.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

/// Index of the material of class `id` in the model.
uint32_t index_of(const Model &m, int32_t id)
{
    for (uint32_t i = 1; i < m.materials().size(); ++i)
        if (m.materials()[i].id == id)
            return i;
    ADD_FAILURE() << "no class " << id;
    return 0;
}

/// The first voxel class at or below depth `from`, top down, skipping
/// nulls and the classes in `skip`; NULL_CLASS if none.
int32_t first_below(const sbrt_test::Voxels &v, int row, int col, int from,
                    const std::set<int32_t> &skip = {})
{
    for (int z = from; z >= 0; --z) {
        const int32_t id = v.classes[(size_t(z) * v.frame.rows + row) * v.frame.cols + col];
        if (id != NULL_CLASS && !skip.count(id))
            return id;
    }
    return NULL_CLASS;
}

} // namespace

TEST(HiddenMaterials, TopViewIsTheSubcropMap)
{
    const auto v = sbrt_test::random_voxels(5, 17, 13, 30, 6);
    const Model full = sbrt_test::build_model(v);
    const std::set<int32_t> hidden_ids = {-13, 1, 15};
    std::vector<uint32_t> hidden;
    for (int32_t id : hidden_ids)
        hidden.push_back(index_of(full, id));
    const Model m = hide_materials(full, hidden);
    m.validate(); // maximal runs, no trailing empty interval
    EXPECT_LT(m.intervals().size(), full.intervals().size());
    const Frame &f = v.frame;
    const Tracer tracer(m, 1.0);
    const Camera cam = sbrt_test::top_camera(f, 1e4);
    const HitImage hits = trace_image(tracer, cam, 2);
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            const Hit &h = hits[size_t(row) * f.cols + col];
            const int32_t got = h.is_hit() ? m.materials()[h.material].id : NULL_CLASS;
            ASSERT_EQ(got, first_below(v, row, col, f.depths - 1, hidden_ids))
                << row << "," << col;
        }
    EXPECT_THROW(hide_materials(full, {EMPTY}), Error);
    EXPECT_THROW(hide_materials(full, {uint32_t(full.materials().size())}), Error);
}

namespace {

/// The hits of `camera` through a tracer of `m` and `scene`.
HitImage hits_of(const Model &m, Scene scene, const Camera &camera)
{
    const Tracer tracer(m, 2.0, std::move(scene));
    return trace_image(tracer, camera, 2);
}

} // namespace

TEST(HiddenMaterials, HiddenWhileTracingIsTheModelWithoutThem)
{
    // every hit as exact as with the strata removed from the model: t,
    // point, face, normal, class, and the light of translucent strata
    const auto v = sbrt_test::random_voxels(11, 19, 23, 28, 6);
    const Model full = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const glm::dvec3 centre((f.west + f.east) / 2, (f.south + f.north) / 2,
                            f.bottom + f.depths * f.tb_res());
    const std::vector<Camera> cameras = {
        sbrt_test::top_camera(f, 1e4),
        Camera::perspective(centre + glm::dvec3(-40, -55, 60), centre, 40, 48, 64),
        Camera::perspective(centre + glm::dvec3(35, 20, -70), centre, 50, 40, 52),
        Camera::orthographic(centre + glm::dvec3(60, -10, 20), centre, 50, 36, 48)};
    size_t hits = 0, differing_from_full = 0;
    for (const std::vector<int32_t> &ids : {std::vector<int32_t>{-13}, {1, 15}, {-13, 1, 15, 8}}) {
        std::vector<uint32_t> hidden;
        std::vector<uint8_t> mask(full.materials().size(), 0);
        for (const int32_t id : ids) {
            hidden.push_back(index_of(full, id));
            mask[hidden.back()] = 1;
        }
        const Model removed = hide_materials(full, hidden);
        for (const bool cut_and_translucent : {false, true})
            for (const bool skipping : {true, false}) {
                Scene scene = cut_and_translucent ? sbrt_test::cut_and_translucent_scene(full)
                                                  : Scene{};
                scene.skip_empty_space = skipping;
                Scene marked = scene;
                marked.hidden = mask;
                for (const Camera &camera : cameras) {
                    const HitImage want = hits_of(removed, scene, camera);
                    const HitImage got = hits_of(full, marked, camera);
                    const HitImage shown = hits_of(full, scene, camera);
                    for (size_t i = 0; i < want.size(); ++i) {
                        const Hit &a = want[i];
                        ASSERT_TRUE(sbrt_test::identical_hits(a, got[i])) << i;
                        if (!a.is_hit())
                            continue;
                        ++hits;
                        differing_from_full += shown[i].material != a.material;
                    }
                }
            }
    }
    EXPECT_GT(hits, 10000u);
    EXPECT_GT(differing_from_full, 1000u); // the hidden strata were in view
    // a mask of the wrong size, and one beside boreholes (they read the
    // stacks themselves)
    Scene wrong;
    wrong.hidden.assign(full.materials().size() + 1, 0);
    EXPECT_THROW(Tracer(full, 1.0, wrong), Error);
    Scene with_borehole;
    with_borehole.hidden.assign(full.materials().size(), 0);
    with_borehole.boreholes = {sbrt_test::borehole_at(full, centre.x, centre.y)};
    with_borehole.borehole_radius = 1;
    EXPECT_THROW(Tracer(full, 1.0, with_borehole), Error);
}

TEST(ClipPlanes, HorizontalCutIsAVoxelSlice)
{
    const auto v = sbrt_test::random_voxels(9, 15, 12, 24, 7);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    for (int level : {3, 11, 20}) {
        // the plane through the centres of the voxels of `level`
        const double z0 = f.bottom + (level + 0.5) * f.tb_res();
        for (double zexag : {1.0, 4.0}) {
            const Tracer tracer(m, zexag, {{{0, 0, z0}, {0, 0, 1}}});
            const Camera cam = Camera::top(
                f.north, f.south, f.east, f.west,
                tracer.frame().exaggerated_from_map({0, 0, f.top}).z + 10, f.rows, f.cols);
            const HitImage hits = trace_image(tracer, cam, 2);
            for (int row = 0; row < f.rows; ++row)
                for (int col = 0; col < f.cols; ++col) {
                    const Hit &h = hits[size_t(row) * f.cols + col];
                    const int32_t got =
                        h.is_hit() ? m.materials()[h.material].id : NULL_CLASS;
                    const int32_t want = first_below(v, row, col, level);
                    ASSERT_EQ(got, want) << level << ": " << row << "," << col;
                    const int32_t at_level =
                        v.classes[(size_t(level) * f.rows + row) * f.cols + col];
                    if (at_level != NULL_CLASS) {
                        // cut open: the hit lies on the plane, facing up
                        EXPECT_EQ(h.face, Face::plane);
                        EXPECT_NEAR(h.point.z, z0, 1e-9);
                        EXPECT_NEAR(h.normal.z, 1, 1e-12);
                    }
                }
        }
    }
}

TEST(ClipPlanes, RemovedSideIsWhereTheNormalPoints)
{
    const auto v = sbrt_test::random_voxels(3, 10, 10, 10, 3);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const glm::dvec3 mid((f.west + f.east) / 2, (f.south + f.north) / 2, f.top);
    // removing everything east of the middle: rays there miss
    const Tracer tracer(m, 1.0, {{mid, {1, 0, 0}}});
    const Camera cam = sbrt_test::top_camera(f, 1e4);
    const HitImage hits = trace_image(tracer, cam, 1);
    for (int row = 0; row < f.rows; ++row)
        for (int col = f.cols / 2; col < f.cols; ++col)
            EXPECT_FALSE(hits[size_t(row) * f.cols + col].is_hit());
    EXPECT_THROW(Tracer(m, 1.0, {{mid, {0, 0, 0}}}), Error);
    EXPECT_THROW(Tracer(m, 1.0, std::vector<ClipPlane>(MAX_CLIP_PLANES + 1, {mid, {1, 0, 0}})),
                 Error);
}

TEST(ClipPlanes, ASectionSeenHeadOnShowsItsClassesAsTheLegend)
{
    // a south-facing cut seen from the south with the default light (from
    // the north-west, behind it): the cut is drawn in the classes' own
    // colours, not in shadow; the model's other faces stay lit
    const Model m = sbrt_test::geology(30, 40, 20);
    const Frame &f = m.frame();
    const glm::dvec3 mid((f.west + f.east) / 2, (f.south + f.north) / 2, f.bottom);
    const Tracer tracer(m, 2.0, {{mid, {0, -1, 0}}});
    View view;
    view.azimuth = 180;
    view.elevation = 10;
    const Camera camera = view_camera(view, tracer.model(), tracer.frame(), 120, 160);
    Shading shading;
    shading.light = Shading::light_from(315, 45);
    const PixelShader shader(m, shading);
    const HitImage hits = trace_image(tracer, camera, 1);
    int cut = 0, lit_faces = 0;
    for (const Hit &hit : hits) {
        if (!hit.is_hit())
            continue;
        const auto rgb = shader(hit);
        const auto legend = material_color(m, hit.material);
        if (hit.face == Face::plane) {
            ++cut;
            EXPECT_EQ(rgb, legend);
        }
        else if (rgb != legend)
            ++lit_faces;
    }
    EXPECT_GT(cut, 120 * 160 / 20);
    EXPECT_GT(lit_faces, 0);
}
