/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The exact tracer against an independent 3D voxel walk over the
 *            source voxels, on random models and random rays (fixed seeds)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/camera.hpp"
#include "util/error.hpp"
#include "test_support.hpp"
#include "tracing/tracer.hpp"
#include "builders/voxel_builder.hpp"

using namespace sbrt;

namespace {

using sbrt_test::march;
using sbrt_test::VoxelHit;

} // namespace

TEST(Tracer, AgreesWithIndependentVoxelWalk)
{
    int rays = 0, agree = 0, hits = 0;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        auto v = sbrt_test::random_voxels(seed, 9 + seed % 5, 7 + seed % 4,
                                          12 + seed % 9, 6);
        // unit cells: map frame == voxel frame
        v.frame.west = 0;
        v.frame.east = v.frame.cols;
        v.frame.south = 0;
        v.frame.north = v.frame.rows;
        v.frame.bottom = 0;
        v.frame.top = v.frame.depths;
        const Model m = sbrt_test::build_model(v);
        const Tracer tracer(m, 1.0);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int k = 0; k < 3000; ++k) {
            const glm::dvec3 target(v.frame.cols * (0.5 + 0.5 * u(rng)),
                                    v.frame.rows * (0.5 + 0.5 * u(rng)),
                                    v.frame.depths * (0.5 + 0.5 * u(rng)));
            glm::dvec3 dir = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
            const glm::dvec3 origin = target - dir * 60.0;
            const Hit hit = tracer.trace({origin, dir});
            const VoxelHit want = march(v, origin, dir);
            ++rays;
            // the stack's top may lie below the voxel box: compare hits only
            const bool same =
                hit.is_hit() == want.hit &&
                (!want.hit || (m.materials()[hit.material].id == want.id &&
                               std::fabs(hit.t - want.t) < 1e-9));
            agree += same;
            hits += want.hit;
        }
    }
    EXPECT_GT(hits, rays / 4);
    // disagreement only where a ray passes exactly through an edge
    EXPECT_GE(agree, rays - rays / 1000) << agree << " of " << rays;
}

TEST(Tracer, TopViewSeesTheTopmostSolidVoxel)
{
    const auto v = sbrt_test::random_voxels(42, 13, 11, 20, 5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const Camera cam = sbrt_test::top_camera(f, 1e4);
    const Image image = sbrt_test::render_cpu(m, cam, 1.0);
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            int32_t top_id = NULL_CLASS;
            int top_z = -1;
            for (int z = f.depths - 1; z >= 0 && top_id == NULL_CLASS; --z) {
                top_id = v.classes[(size_t(z) * f.rows + row) * f.cols + col];
                top_z = z;
            }
            const size_t i = size_t(row) * f.cols + col;
            ASSERT_EQ(image.material[i], top_id) << row << "," << col;
            if (top_id != NULL_CLASS) {
                EXPECT_NEAR(image.elevation[i], f.bottom + (top_z + 1) * f.tb_res(), 1e-9);
            }
        }
}

TEST(Tracer, ExaggerationKeepsWhatIsHitOnAVerticalRay)
{
    const auto v = sbrt_test::random_voxels(8, 6, 6, 10, 4);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = v.frame;
    const Camera cam = sbrt_test::top_camera(f, 1e5);
    const Image a = sbrt_test::render_cpu(m, cam, 1.0, 1);
    const Image b = sbrt_test::render_cpu(m, cam, 7.5, 1);
    EXPECT_EQ(a.material, b.material);
    for (size_t i = 0; i < a.elevation.size(); ++i)
        if (!std::isnan(a.elevation[i])) {
            EXPECT_NEAR(a.elevation[i], b.elevation[i], 1e-9);
        }
}

TEST(Camera, PixelRowsPlaceAPointWhereProjectDoes)
{
    // perspective, parallel and windows of them: (c / w, r / w) is the
    // pixel position of project's (x, y), w > 0 exactly where it projects
    const Camera cameras[] = {
        Camera::perspective({70, -40, 90}, {30, 20, 0}, 60, 240, 320),
        Camera::orthographic({-50, 300, 400}, {30, 20, 10}, 150, 101, 77),
        Camera::perspective({70, -40, 90}, {30, 20, 0}, 60, 240, 320).window(37, 50, 11, 90),
        Camera::orthographic({-50, 300, 400}, {30, 20, 10}, 150, 101, 77).rows_window(20, 31)};
    std::mt19937 random(5);
    std::uniform_real_distribution<double> at(-200, 200);
    for (const Camera &camera : cameras) {
        const std::array<glm::dvec4, 3> rows = camera.pixel_rows();
        int projected = 0;
        for (int k = 0; k < 200; ++k) {
            const glm::dvec4 p(at(random), at(random), at(random), 1);
            double x, y;
            const glm::dvec4 v(glm::dvec3(p) - camera.origin(), 1);
            const double w = glm::dot(rows[2], v);
            if (!camera.project(glm::dvec3(p), x, y)) {
                EXPECT_LE(w, 0);
                continue;
            }
            ++projected;
            ASSERT_GT(w, 0);
            EXPECT_NEAR(glm::dot(rows[0], v) / w, (x + 1) / 2 * camera.cols() - 0.5, 1e-9);
            EXPECT_NEAR(glm::dot(rows[1], v) / w, (1 - y) / 2 * camera.rows() - 0.5, 1e-9);
        }
        EXPECT_GT(projected, 50);
    }
}

TEST(Camera, BadCamerasAreErrors)
{
    EXPECT_THROW(Camera::perspective({1, 2, 3}, {1, 2, 3}, 40, 10, 10), Error);
    EXPECT_THROW(Camera::perspective({0, 0, 0}, {1, 0, 0}, 180, 10, 10), Error);
    EXPECT_THROW(Camera::perspective({0, 0, 0}, {1, 0, 0}, 40, 0, 10), Error);
    EXPECT_THROW(Camera::orthographic({0, 0, 0}, {1, 0, 0}, -1, 10, 10), Error);
}

TEST(Camera, PixelCentresFollowTheNdcConvention)
{
    const Camera cam = Camera::perspective({0, 0, 0}, {0, 1, 0}, 90, 2, 4);
    // pixel (0, 3): ndc (0.75, 0.5), aspect 2 -> direction (1.5, 1, 0.5)
    const Ray r = cam.ray(0, 3);
    const glm::dvec3 want = glm::normalize(glm::dvec3(1.5, 1, 0.5));
    EXPECT_NEAR(glm::length(r.direction - want), 0, 1e-12);
}
