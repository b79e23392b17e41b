/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Views turned into cameras (framing, azimuth convention,
 *            orthographic start) and the scene parts made from user input
 *            (section facing the camera, translucent strata, borehole logs)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <array>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "util/error.hpp"
#include "gpu_compare.hpp"
#include "scene/scene_parts.hpp"
#include "shading/shading.hpp"
#include "scene/view.hpp"

using namespace sbrt;

namespace {

/// Extent of the model's framing hull in normalised device coordinates:
/// x_low, x_high, y_low, y_high; false where a point is behind the camera.
bool hull_extent(const Tracer &t, const Camera &camera, double e[4])
{
    e[0] = e[2] = 1e9;
    e[1] = e[3] = -1e9;
    for (const glm::dvec3 &p : framing_hull(t.model(), t.frame())) {
        double x, y;
        if (!camera.project(p, x, y))
            return false;
        e[0] = std::min(e[0], x);
        e[1] = std::max(e[1], x);
        e[2] = std::min(e[2], y);
        e[3] = std::max(e[3], y);
    }
    return true;
}

/// Rows and columns of the image's border (`margin` of its size) where
/// the traced model shows: [top, bottom, left, right] counts of hits.
std::array<int, 4> hits_near_edges(const Tracer &t, const Camera &c, double margin)
{
    std::array<int, 4> near{0, 0, 0, 0};
    const int mr = std::max(1, int(margin * c.rows())), mc = std::max(1, int(margin * c.cols()));
    for (int r = 0; r < c.rows(); ++r)
        for (int col = 0; col < c.cols(); ++col) {
            if (!t.trace(c.ray(r, col)).is_hit())
                continue;
            near[0] += r < mr;
            near[1] += r >= c.rows() - mr;
            near[2] += col < mc;
            near[3] += col >= c.cols() - mc;
        }
    return near;
}

} // namespace

TEST(View, DefaultViewFramesTheModelTightlyAndCentred)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer t(m, 2.0);
    for (const ViewKind kind : {ViewKind::perspective, ViewKind::orthographic})
        for (double azimuth : {0.0, 135.0, 225.0, 300.0})
            for (double elevation : {5.0, 30.0, 70.0})
                for (const auto &[rows, cols] : {std::pair{480, 640}, {884, 1056}, {600, 300}}) {
                    View v;
                    v.kind = kind;
                    v.azimuth = azimuth;
                    v.elevation = elevation;
                    const Camera camera = view_camera(v, t.model(), t.frame(), rows, cols);
                    double e[4];
                    ASSERT_TRUE(hull_extent(t, camera, e));
                    const std::string what = std::to_string(int(kind)) + " " +
                                             std::to_string(azimuth) + " " +
                                             std::to_string(elevation) + " " +
                                             std::to_string(rows) + "x" + std::to_string(cols);
                    for (double edge : {-e[0], e[1], -e[2], e[3]})
                        EXPECT_LE(edge, 0.95 + 1e-6) << what;
                    // centred on both axes; the tighter axis reaches the
                    // margin on both sides
                    EXPECT_NEAR(e[0] + e[1], 0, 0.02) << what;
                    EXPECT_NEAR(e[2] + e[3], 0, 0.02) << what;
                    EXPECT_GT(std::max(std::min(-e[0], e[1]), std::min(-e[2], e[3])), 0.93)
                        << what;
                }
}

TEST(View, TracedModelFillsTheImageWithoutTouchingItsBorder)
{
    // what the rays see, not the hull: nothing cut off, no empty band
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer t(m, 2.0);
    for (const ViewKind kind : {ViewKind::perspective, ViewKind::orthographic})
        for (double azimuth : {45.0, 225.0})
            for (const auto &[rows, cols] : {std::pair{48, 64}, {64, 32}}) {
                View v;
                v.kind = kind;
                v.azimuth = azimuth;
                const Camera c = view_camera(v, t.model(), t.frame(), rows, cols);
                const auto outer = hits_near_edges(t, c, 0.02);
                EXPECT_EQ(outer, (std::array<int, 4>{0, 0, 0, 0}))
                    << int(kind) << " " << azimuth << " " << rows << "x" << cols;
                const auto band = hits_near_edges(t, c, 0.09);
                // the tighter axis: hits within 9 % of both of its edges
                const bool vertical = band[0] > 0 && band[1] > 0;
                const bool horizontal = band[2] > 0 && band[3] > 0;
                EXPECT_TRUE(vertical || horizontal)
                    << int(kind) << " " << azimuth << " " << rows << "x" << cols << " "
                    << band[0] << " " << band[1] << " " << band[2] << " " << band[3];
            }
}

TEST(View, HullHoldsEveryColumnAndIsTighterThanTheBox)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Tracer t(m, 2.0);
    const std::vector<glm::dvec3> hull = framing_hull(t.model(), t.frame());
    ASSERT_EQ(hull.size(), 8u * 8u * 8u);
    double hull_top_sum = 0;
    for (const glm::dvec3 &p : hull) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(p[k], t.frame().corner(0)[k] - 1e-6);
            EXPECT_LE(p[k], t.frame().corner(7)[k] + 1e-6);
        }
        hull_top_sum += p.z;
    }
    // every column's top lies under the hull point above its block
    const Frame &f = m.frame();
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            const uint64_t cell = m.cell_index(row, col);
            if (m.stack_size(cell) == 0)
                continue;
            const double top_local = m.intervals()[m.stack_end(cell) - 1].top;
            const double top =
                t.frame().exaggerated_from_map(t.frame().map_from_local({0, 0, top_local})).z;
            const double x = f.west + (col + 0.5) * f.ew_res(),
                         y = f.north - (row + 0.5) * f.ns_res();
            double above = -1e300;
            for (const glm::dvec3 &p : hull)
                if (std::fabs(p.x - x) <= f.ew_res() * f.cols / 8.0 &&
                    std::fabs(p.y - y) <= f.ns_res() * f.rows / 8.0)
                    above = std::max(above, p.z);
            EXPECT_GE(above, top - 1e-6) << row << " " << col;
        }
    // the geology model's terrain is not flat: lower on average than the box
    EXPECT_LT(hull_top_sum / double(hull.size()), (t.frame().corner(0).z + t.frame().corner(7).z) / 2);
}

TEST(View, AzimuthIsWhereTheCameraLooksFrom)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 1.0);
    View v;
    v.elevation = 20;
    v.distance = 5000;
    v.target = t.frame().map_from_exaggerated(t.frame().centre());
    v.azimuth = 180; // from the south
    Camera c = view_camera(v, t.model(), t.frame(), 40, 50);
    EXPECT_LT(c.origin().y, t.frame().centre().y);
    EXPECT_GT(c.forward().y, 0.9); // looking north
    EXPECT_NEAR(glm::length(c.origin() - t.frame().centre()), 5000, 1e-6);
    v.azimuth = 90; // from the east
    c = view_camera(v, t.model(), t.frame(), 40, 50);
    EXPECT_GT(c.origin().x, t.frame().centre().x);
    EXPECT_LT(c.forward().x, -0.9);
    // position and target win over the angles (map z exaggerated)
    const Tracer t2(m, 3.0);
    v.position = t2.frame().map_from_exaggerated(t2.frame().centre() + glm::dvec3(0, -100, 50));
    v.target = t2.frame().map_from_exaggerated(t2.frame().centre());
    c = view_camera(v, t2.model(), t2.frame(), 40, 50);
    EXPECT_LT(glm::length(c.origin() - (t2.frame().centre() + glm::dvec3(0, -100, 50))), 1e-6);
    v.kind = ViewKind::top;
    EXPECT_THROW(view_camera(v, t2.model(), t2.frame(), 40, 50), Error);
}

TEST(View, OrthographicRaysStartOutsideTheModel)
{
    const Model m = sbrt_test::geology(20, 24, 12);
    const Tracer t(m, 1.0);
    View v;
    v.kind = ViewKind::orthographic;
    v.position = t.frame().centre() + glm::dvec3(1, 1, 1); // inside the box
    const Camera c = view_camera(v, t.model(), t.frame(), 30, 40);
    EXPECT_TRUE(c.parallel());
    EXPECT_GT(glm::length(c.origin() - t.frame().centre()), t.frame().radius());
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

TEST(SceneParts, LogValuesAsElevations)
{
    EXPECT_EQ(parse_log_reference("depth"), LogReference::depth);
    EXPECT_EQ(parse_log_reference("elevation"), LogReference::elevation);
    EXPECT_THROW(parse_log_reference("height"), Error);
    EXPECT_EQ(std::string(log_reference_name(LogReference::depth)), "depth");
    // depths below a collar at 120 m; elevations as they are
    EXPECT_EQ(log_elevation(40, LogReference::depth, 120), 80);
    EXPECT_EQ(log_elevation(40, LogReference::elevation, 120), 40);
}
