/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Views turned into cameras (framing, azimuth convention,
 *            orthographic start) and the scene parts made from user input
 *            (section facing the camera, translucent strata, borehole logs)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "error.hpp"
#include "gpu_compare.hpp"
#include "scene_parts.hpp"
#include "shading.hpp"
#include "view.hpp"

using namespace sbrt;

namespace {

/// Largest |x| and |y| of the model's corners in normalised device
/// coordinates; false where one is behind the camera.
bool corner_extent(const Tracer &t, const Camera &camera, double &x_max, double &y_max)
{
    x_max = y_max = 0;
    for (int k = 0; k < 8; ++k) {
        double x, y;
        if (!camera.project(t.corner(k), x, y))
            return false;
        x_max = std::max(x_max, std::fabs(x));
        y_max = std::max(y_max, std::fabs(y));
    }
    return true;
}

} // namespace

TEST(View, DefaultDistanceFramesTheWholeModelTightly)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer t(m, 2.0);
    for (double azimuth : {0.0, 135.0, 225.0, 300.0})
        for (double elevation : {5.0, 30.0, 70.0})
            for (const auto &[rows, cols] : {std::pair{480, 640}, {884, 1056}, {600, 300}}) {
                View v;
                v.azimuth = azimuth;
                v.elevation = elevation;
                const Camera camera = view_camera(v, t, rows, cols);
                double x, y;
                ASSERT_TRUE(corner_extent(t, camera, x, y));
                EXPECT_LE(std::max(x, y), 0.95 + 1e-6) << azimuth << " " << elevation << " " << rows << "x" << cols << " x " << x << " y " << y;
                // tight: the box reaches the frame's margin on one side
                EXPECT_GT(std::max(x, y), 0.94) << azimuth << " " << elevation;
            }
}

TEST(View, AzimuthIsWhereTheCameraLooksFrom)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 1.0);
    View v;
    v.elevation = 20;
    v.distance = 5000;
    v.azimuth = 180; // from the south
    Camera c = view_camera(v, t, 40, 50);
    EXPECT_LT(c.origin().y, t.centre().y);
    EXPECT_GT(c.forward().y, 0.9); // looking north
    EXPECT_NEAR(glm::length(c.origin() - t.centre()), 5000, 1e-6);
    v.azimuth = 90; // from the east
    c = view_camera(v, t, 40, 50);
    EXPECT_GT(c.origin().x, t.centre().x);
    EXPECT_LT(c.forward().x, -0.9);
    // position and target win over the angles (map z exaggerated)
    const Tracer t2(m, 3.0);
    v.position = t2.unexaggerate(t2.centre() + glm::dvec3(0, -100, 50));
    v.target = t2.unexaggerate(t2.centre());
    c = view_camera(v, t2, 40, 50);
    EXPECT_LT(glm::length(c.origin() - (t2.centre() + glm::dvec3(0, -100, 50))), 1e-6);
    v.kind = ViewKind::top;
    EXPECT_THROW(view_camera(v, t2, 40, 50), Error);
}

TEST(View, OrthographicRaysStartOutsideTheModel)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 1.0);
    View v;
    v.kind = ViewKind::orthographic;
    v.position = t.centre() + glm::dvec3(1, 1, 1); // inside the box
    const Camera c = view_camera(v, t, 30, 40);
    EXPECT_TRUE(c.parallel());
    EXPECT_GT(glm::length(c.origin() - t.centre()), t.radius());
}

TEST(SceneParts, SectionRemovesTheCameraSide)
{
    const glm::dvec2 a(0, 0), b(100, 0); // west-east line, normal north or south
    for (double y : {-500.0, 500.0}) {
        const Camera c = Camera::perspective({50, y, 100}, {50, 0, 0}, 40, 20, 20);
        const ClipPlane p = section_plane(a, b, c);
        // the camera's side is f > 0: removed
        EXPECT_GT(glm::dot(p.normal, c.origin() - p.point), 0) << y;
        const Camera o = Camera::orthographic({50, y, 100}, {50, 0, 0}, 50, 20, 20);
        EXPECT_GT(glm::dot(section_plane(a, b, o).normal, -o.forward()), 0) << y;
    }
    EXPECT_THROW(section_plane(a, a, Camera::perspective({0, 0, 9}, {0, 0, 0}, 40, 2, 2)),
                 Error);
}

TEST(SceneParts, TranslucencyOfTheStrataAskedFor)
{
    const Model m = sbrt_test::geology(10, 12, 8);
    EXPECT_TRUE(make_translucency(m, {}, 10).empty());
    const Translucency tr = make_translucency(m, {{2, 0.5}, {3, 1.0}}, 10);
    ASSERT_EQ(tr.extinction.size(), m.materials().size());
    EXPECT_DOUBLE_EQ(std::exp(-tr.extinction[2] * 10), 0.5); // half over 10 units
    EXPECT_TRUE(tr.opaque(3));                                // alpha 1
    EXPECT_TRUE(tr.opaque(1));
    const auto rgb = material_color(m, 2);
    EXPECT_DOUBLE_EQ(tr.color[2].r, rgb[0] / 255.0);
    EXPECT_THROW(make_translucency(m, {{0, 0.5}}, 10), Error);
    EXPECT_THROW(make_translucency(m, {{2, 0.5}}, 0), Error);
}

TEST(SceneParts, LogStackFromLoggedIntervals)
{
    Frame f;
    f.bottom = 100;
    f.top = 200;
    f.depths = 100; // one local unit per metre
    // out of order, a gap, an overlap, a hidden class, one below the model
    const std::vector<Interval> stack =
        log_stack(f,
                  {{150, 160, 3}, {100, 120, 1}, {125, 140, 2}, {135, 150, 4},
                   {50, 90, 5}, {160, 170, 6}, {170, 180, 7}, {180, 190, 8}},
                  {7, 8});
    const std::vector<std::pair<uint32_t, float>> want = {
        {1, 20}, {EMPTY, 25}, {2, 40}, {4, 50}, {3, 60}, {6, 70}};
    ASSERT_EQ(stack.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(stack[i].material, want[i].first) << i;
        EXPECT_FLOAT_EQ(stack[i].top, want[i].second) << i;
    }
    // equal neighbours merge
    const auto merged = log_stack(f, {{100, 110, 2}, {110, 130, 2}}, {});
    ASSERT_EQ(merged.size(), 1u);
    EXPECT_FLOAT_EQ(merged[0].top, 30);
}
