/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Numerical stress: huge coordinates, tiny and huge cells, thin
 *            layers, extreme exaggeration, grazing rays, rays along cell
 *            walls and through corners, cameras inside solid rock, inside
 *            a cave and very far away, images of 1, 4M and (band by band)
 *            67M pixels. The
 *            GPU (EGL, llvmpipe here) against the CPU reference, which is
 *            checked against the voxels; no NaN, no holes. Each case prints
 *            a line of the stress matrix ("[ stress ] case agreement
 *            depth-error").
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gpu_compare.hpp"

using namespace sbrt;
using namespace sbrt_test;

namespace {

/// The GPU against the CPU on one camera: agreement as in the render-core
/// issue, the largest depth error of the agreeing hits (share of the
/// model's size), and no NaN anywhere.
void stress(const char *name, const Tracer &tracer, const Camera &camera,
            size_t min_hits = 1)
{
    static std::unique_ptr<sbrt_gl::GlContext> context = make_context("egl");
    ASSERT_TRUE(context);
    sbrt_gl::GpuTracer gpu(*context, tracer);
    const HitImage want = trace_image(tracer, camera, 2);
    const HitImage got = gpu.trace_image(camera, 2);
    const double size = 2 * tracer.frame().radius();
    size_t hits = 0, agreeing = 0;
    double worst = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        for (const Hit *h : {&want[i], &got[i]}) {
            if (h->is_hit()) {
                ASSERT_TRUE(std::isfinite(h->t) && std::isfinite(glm::length(h->point)) &&
                            std::isfinite(glm::length(h->normal)))
                    << name << ": NaN in pixel " << i;
            }
        }
        hits += want[i].is_hit();
        if (want[i].material != got[i].material)
            continue;
        if (!want[i].is_hit()) {
            ++agreeing;
            continue;
        }
        const double error = std::fabs(want[i].t - got[i].t) / size;
        worst = std::max(worst, error);
        agreeing += error < 1e-4;
    }
    const double share = 100.0 * double(agreeing) / double(want.size());
    std::printf("[ stress ] %-34s %8.3f %% agree  depth error %.1e of the size  "
                "(%zu pixels, %zu hits)\n",
                name, share, worst, want.size(), hits);
    EXPECT_GE(hits, min_hits) << name;
    EXPECT_GE(agreeing, want.size() - want.size() / 1000) << name;
}

/// An oblique view of the whole model.
Camera oblique(const Tracer &tracer, int rows = 90, int cols = 120, double elevation = 0.45)
{
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    return Camera::perspective(c + glm::dvec3(0.5, -0.75, elevation) * size, c, 40,
                               rows, cols);
}

} // namespace

TEST(Stress, HugeCoordinates)
{
    for (double offset : {0.0, 1e5, 1e6, 1e7}) {
        Placement at;
        at.west = offset + 0.5;
        at.south = offset + 0.25;
        const Model m = geology(30, 40, 24, at);
        const Tracer tracer(m, 2.0);
        const std::string name = "map offset " + std::to_string(int(offset)) + " m";
        stress(name.c_str(), tracer, oblique(tracer), 1000);
        // the CPU sees the same as at the origin (the camera moved along)
        const Model origin = geology(30, 40, 24, Placement{0.5, 0.25});
        const Tracer at_origin(origin, 2.0);
        const auto a = trace_image(tracer, oblique(tracer), 2);
        const auto b = trace_image(at_origin, oblique(at_origin), 2);
        size_t same = 0;
        for (size_t i = 0; i < a.size(); ++i)
            same += a[i].material == b[i].material;
        EXPECT_GE(same, a.size() - a.size() / 1000) << name;
    }
}

TEST(Stress, TinyAndHugeCells)
{
    for (double cell : {0.01, 1000.0}) {
        Placement at;
        at.cell = cell;
        at.tb = cell / 5;
        at.bottom = -100 * cell;
        const Model m = geology(30, 40, 24, at);
        const Tracer tracer(m, 2.0);
        const std::string name = "cells of " + std::to_string(cell) + " m";
        stress(name.c_str(), tracer, oblique(tracer), 1000);
    }
}

TEST(Stress, ThinLayersAreNeverSkipped)
{
    // every stack: a thick base, a layer one voxel thick, one 1e-4 voxel
    // thick, and on top another 1e-4 voxel layer
    Frame f;
    f.rows = 12;
    f.cols = 16;
    f.depths = 20;
    f.west = 1000;
    f.east = 1000 + 16 * 10.0;
    f.south = 2000;
    f.north = 2000 + 12 * 10.0;
    f.bottom = 0;
    f.top = 40;
    std::vector<Material> materials(5);
    for (int k = 1; k < 5; ++k)
        materials[size_t(k)].id = k;
    std::vector<uint32_t> offsets(f.cells() + 1);
    Intervals intervals;
    for (uint64_t c = 0; c < f.cells(); ++c) {
        const float base = 10.0f + float(c % 7);
        for (Interval iv : {Interval{1, base}, Interval{2, base + 1.0f},
                            Interval{3, base + 1.0001f}, Interval{4, base + 1.0002f}})
            intervals.push_back(iv);
        offsets[c + 1] = uint32_t(intervals.size());
    }
    const Model m(f, materials, offsets, intervals);
    m.validate();
    const Tracer tracer(m, 1.0);
    // from above every pixel sees the 1e-4 voxel layer on top
    const Camera top = top_camera(f, 1e3);
    for (const Hit &h : trace_image(tracer, top, 2))
        ASSERT_EQ(h.material, 4u);
    stress("layers of 1e-4 voxel, top view", tracer, top, f.cells());
    stress("layers of 1e-4 voxel, oblique", tracer, oblique(tracer), 1000);
    // a plane halfway through the upper 1e-4 voxel layer of the stacks
    // based at 10: their cut face shows that layer, exactly at the plane
    const double z = f.bottom + (10 + 1.00015) * f.tb_res();
    const Tracer cut(m, 1.0, std::vector<ClipPlane>{{{0, 0, z}, {0, 0, 1}}});
    const auto cut_hits = trace_image(cut, top, 2);
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            if (m.cell_index(row, col) % 7 != 0)
                continue;
            const Hit &h = cut_hits[size_t(row) * f.cols + col];
            ASSERT_EQ(h.material, 4u);
            ASSERT_EQ(h.face, Face::plane);
            ASSERT_NEAR(h.point.z, z, 1e-9);
        }
    stress("1e-4 voxel layer cut by a plane", cut, top, f.cells());
}

TEST(Stress, ExtremeExaggeration)
{
    const Model m = geology(30, 40, 24);
    for (double zexag : {0.1, 1000.0}) {
        const Tracer tracer(m, zexag);
        const std::string name = "zexag " + std::to_string(zexag);
        stress(name.c_str(), tracer, oblique(tracer), 100);
    }
}

TEST(Stress, GrazingRays)
{
    const Model m = geology(30, 40, 24);
    const Tracer tracer(m, 2.0);
    // 0.01 degrees above the horizon, level with the highest top
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const double top = tracer.frame().corner(7).z;
    const double el = 0.01 * M_PI / 180;
    const glm::dvec3 eye(c.x - size, c.y - 0.3 * size, top + size * std::tan(el));
    stress("grazing, 0.01 degrees", tracer,
           Camera::perspective(eye, glm::dvec3(c.x, c.y, top), 30, 80, 120), 100);
}

TEST(Stress, RaysAlongCellWallsAndThroughCorners)
{
    const auto v = random_voxels(2, 14, 18, 20, 5);
    // solid bottom layer: every column holds something
    auto solid = v;
    for (size_t i = 0; i < solid.frame.cells(); ++i)
        solid.classes[i] = 1;
    const Model m = build_model(solid);
    const Frame &f = m.frame();
    const Tracer tracer(m, 1.0);
    // a top view whose pixel centres lie on the cell corners: rays down
    // along four walls at once
    const double ew = f.ew_res(), ns = f.ns_res();
    const Camera corners = Camera::top(f.north - ns, f.south + ns - 2 * ns + ns, f.east - ew,
                                       f.west, 1e3, f.rows - 1, f.cols - 1);
    stress("top view through cell corners", tracer, corners, size_t(f.rows - 1) * (f.cols - 1));
    for (const Hit &h : trace_image(tracer, corners, 2))
        ASSERT_TRUE(h.is_hit()); // no holes between the cells
    // horizontal rays along a wall plane (x on a wall, through the grid)
    const double x_wall = f.west + 7 * ew;
    const glm::dvec3 eye(x_wall, f.south - 5 * ns, f.bottom + 0.5 * f.tb_res());
    stress("along a wall, level", tracer,
           Camera::orthographic(eye, eye + glm::dvec3(0, 1, 0), 4 * f.tb_res(), 8, 8), 1);
}

TEST(Stress, CameraInsideRockInsideACaveAndFarAway)
{
    const int rows = 30, cols = 40, depths = 24;
    const Model m = geology(rows, cols, depths);
    const Frame &f = m.frame();
    const Tracer tracer(m, 1.0);
    // inside solid rock: every ray hits where it starts
    const glm::dvec3 rock(f.west + 3.5 * f.ew_res(), f.north - 3.5 * f.ns_res(),
                          f.bottom + 2.5 * f.tb_res());
    const Camera in_rock = Camera::perspective(rock, rock + glm::dvec3(1, 0.3, 0.1), 60, 20, 30);
    for (const Hit &h : trace_image(tracer, in_rock, 2))
        ASSERT_TRUE(h.is_hit() && h.t == 0);
    stress("camera inside rock", tracer, in_rock, 600);
    // inside the cave of geology(): centred on column cols/2, a third up
    const glm::dvec3 cave(f.west + (cols / 2.0) * f.ew_res(), f.north - 0.6 * rows * f.ns_res(),
                          f.bottom + (depths / 3.0) * f.tb_res());
    const Camera in_cave = Camera::perspective(cave, cave + glm::dvec3(0.2, 1, 0.05), 90, 40, 60);
    const auto cave_hits = trace_image(tracer, in_cave, 2);
    size_t away = 0;
    for (const Hit &h : cave_hits)
        away += h.is_hit() && h.t > 0;
    EXPECT_EQ(away, cave_hits.size()); // walls all round, none at the eye
    stress("camera inside a cave", tracer, in_cave, 2400);
    // a million model sizes away, with the field of view to match
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    const glm::dvec3 far = c + 1e6 * size * glm::normalize(glm::dvec3(0.5, -0.75, 0.45));
    const double fov = 2 * std::atan(0.6 / 1e6) * 180 / M_PI;
    stress("1e6 model sizes away, perspective", tracer,
           Camera::perspective(far, c, fov, 60, 80), 500);
    stress("1e6 model sizes away, orthographic", tracer,
           Camera::orthographic(far, c, 1.2 * size, 60, 80), 500);
}

TEST(Stress, OnePixelAndFourMegapixelImages)
{
    const Model m = geology(30, 40, 24);
    const Tracer tracer(m, 2.0);
    const glm::dvec3 c = tracer.frame().centre();
    stress("1 x 1 image", tracer,
           Camera::perspective(c + glm::dvec3(0, 0, 2 * tracer.frame().radius()), c, 10, 1, 1), 1);
    stress("2048 x 2048 image", tracer, oblique(tracer, 2048, 2048), 1000000);
}

TEST(Stress, EightThousandPixelImageBandByBand)
{
    // 8192 x 8192 rays: whole, the CPU's hits alone would take 4.8 GB and
    // the GPU's records 2 GB, so the image is checked band by band; a
    // window of its rows traces the same rays as the whole image
    const Model m = geology(30, 40, 24);
    const Tracer tracer(m, 2.0);
    const int side = 8192;
    const glm::dvec3 c = tracer.frame().centre();
    const double size = 2 * tracer.frame().radius();
    for (const Camera &image :
         {oblique(tracer, side, side),
          Camera::orthographic(c + glm::dvec3(1, -2, 1) * size, c, size, side, side)}) {
        for (int first : {0, 4000, side - 16}) {
            const Camera band = image.rows_window(first, 16);
            for (int r : {0, 7, 15})
                for (int col : {0, side / 2, side - 1}) {
                    const Ray a = image.ray(first + r, col), b = band.ray(r, col);
                    EXPECT_LT(glm::length(a.direction - b.direction), 1e-14);
                    EXPECT_LT(glm::length(a.origin - b.origin), 1e-12 * size);
                }
        }
    }
    EXPECT_THROW(oblique(tracer, side, side).rows_window(side - 8, 16), Error);
    // bands across the whole image, GPU against CPU; the middle ones cross
    // the model
    const Camera image = oblique(tracer, side, side);
    for (int first : {0, 2048, 4080, 6144, side - 32}) {
        const std::string name = "8192 x 8192, rows " + std::to_string(first) + "+32";
        const bool middle = first > 0 && first < side - 32;
        stress(name.c_str(), tracer, image.rows_window(first, 32), middle ? 1000 : 0);
    }
}
