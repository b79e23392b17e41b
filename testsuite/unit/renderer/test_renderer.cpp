/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The streamed renderer (Renderer) against the whole-image
 *            reference (trace_image, then shade): the same colour,
 *            material, elevation and depth, pixel for pixel, for face and
 *            kernel normals (smoothed too), any band height, perspective,
 *            parallel and close-up cameras, inside the model, overlays,
 *            hidden strata and a GPU-like row tracer; bounded windows;
 *            exceptions of worker threads and of the sink reach the caller
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "util/error.hpp"
#include "gpu_compare.hpp"
#include "util/parallel.hpp"
#include "renderer.hpp"
#include "test_support.hpp"

using namespace sbrt;

namespace {

Camera view(const Tracer &t, double azimuth, double elevation, double distance = 2.2,
            int rows = 61, int cols = 83)
{
    const double a = glm::radians(azimuth), e = glm::radians(elevation);
    const glm::dvec3 dir(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
    return Camera::perspective(t.frame().centre() + distance * t.frame().radius() * dir, t.frame().centre(), 40,
                               rows, cols);
}

/// Bitwise equality of doubles, NaN equal to NaN.
bool same(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

/// The streamed image of `renderer` equals the reference of its tracer and
/// shading, for every output.
void expect_as_reference(const Renderer &renderer, const Camera &camera,
                         RowTracer *rows = nullptr, const std::string &what = "")
{
    const Tracer &tracer = renderer.tracer();
    const Image want = shade(tracer, camera, trace_image(tracer, camera, 2),
                             renderer.shading(), 2);
    const Image got = renderer.render_image(camera, {true, true, true}, rows);
    ASSERT_EQ(got.rgb.size(), want.rgb.size());
    size_t rgb = 0, material = 0, elevation = 0, depth = 0;
    for (size_t i = 0; i < want.material.size(); ++i) {
        rgb += std::memcmp(&got.rgb[i * 3], &want.rgb[i * 3], 3) != 0;
        material += got.material[i] != want.material[i];
        elevation += !same(got.elevation[i], want.elevation[i]);
        depth += !same(got.depth[i], want.depth[i]);
    }
    EXPECT_EQ(rgb, 0u) << what;
    EXPECT_EQ(material, 0u) << what;
    EXPECT_EQ(elevation, 0u) << what;
    EXPECT_EQ(depth, 0u) << what;
}

Shading kernel_shading(int k, double smooth)
{
    Shading s;
    s.normals = Normals::kernel;
    s.kernel = k;
    s.smooth = smooth;
    return s;
}

/// Traces through a CPU row tracer, as a GPU would: whole bands asked
/// for, counted.
class CountingRows : public RowTracer {
public:
    CountingRows(const Tracer &tracer, const Camera &camera) : cpu_(tracer, camera, 2) {}
    void trace_rows(int first, int count, Hit *out) override
    {
        rows_traced += count;
        cpu_.trace_rows(first, count, out);
    }
    int rows_traced = 0;

private:
    CpuRowTracer cpu_;
};

} // namespace

TEST(Renderer, FaceNormalsAsTheReferenceForAnyBandHeight)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    for (int band_rows : {0, 1, 7, 61, 500}) {
        const Renderer renderer(m, 2.0, Scene{}, Shading{}, {2, true, band_rows});
        for (double elevation : {70.0, 25.0, 2.0})
            for (double azimuth : {30.0, 200.0})
                expect_as_reference(renderer, view(renderer.tracer(), azimuth, elevation),
                                    nullptr, "band rows " + std::to_string(band_rows));
    }
}

TEST(Renderer, KernelNormalsAsTheReferenceThroughAWindowOfRows)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    for (const auto &[k, smooth] : {std::pair{3, 0.0}, {5, 0.0}, {7, 1.3}, {11, 2.0}})
        for (int band_rows : {1, 6, 0}) {
            const Renderer renderer(m, 2.0, Scene{}, kernel_shading(k, smooth),
                                    {2, true, band_rows});
            const Tracer &t = renderer.tracer();
            const std::string what = "k " + std::to_string(k) + " smooth " +
                                     std::to_string(smooth) + " band rows " +
                                     std::to_string(band_rows);
            expect_as_reference(renderer, view(t, 40, 30), nullptr, what);
            expect_as_reference(renderer, view(t, 250, 5), nullptr, what);
            // close up: a kernel cell spans many pixels
            expect_as_reference(renderer, view(t, 120, 45, 0.45), nullptr, what + " close");
            // parallel rays from above the top
            const glm::dvec3 c = t.frame().centre();
            expect_as_reference(renderer,
                                Camera::orthographic(c + glm::dvec3(300, -400, 500), c,
                                                     1.5 * t.frame().radius(), 47, 64),
                                nullptr, what + " orthographic");
        }
}

TEST(Renderer, KernelWindowHoldsAHaloNotTheImage)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Renderer renderer(m, 2.0, Scene{}, kernel_shading(5, 1.0), {2, true, 8});
    const Camera camera = view(renderer.tracer(), 40, 30, 2.2, 400, 540);
    CountingRows rows(renderer.tracer(), camera);
    int held = 0;
    const RenderReport report =
        renderer.render(camera, {}, [](const Band &) {}, &rows);
    held = report.most_rows_held;
    EXPECT_LT(held, 100) << "the kernel's window grew towards the whole image";
    EXPECT_GE(held, 8);
    // each row traced about once: a halo is kept, not traced again per band
    EXPECT_LT(rows.rows_traced, 400 + 60);
}

TEST(Renderer, InsideTheModelAndWithHiddenStrataOverlaysAndPlanes)
{
    const Model m = sbrt_test::geology(40, 56, 30);
    const Frame &f = m.frame();
    // the camera inside: kernel cells reach behind it
    {
        const Renderer renderer(m, 2.0, Scene{}, kernel_shading(5, 0.8), {2, true, 5});
        const Tracer &t = renderer.tracer();
        const glm::dvec3 inside = t.frame().centre() + glm::dvec3(0, 0, -0.1 * t.frame().radius());
        expect_as_reference(renderer,
                            Camera::perspective(inside, inside + glm::dvec3(1, 0.3, -0.2),
                                                70, 40, 50),
                            nullptr, "inside");
    }
    // a clip plane and translucent strata
    {
        const Renderer renderer(m, 2.0, sbrt_test::cut_and_translucent_scene(m), Shading{},
                                {2, true, 9});
        expect_as_reference(renderer, view(renderer.tracer(), 60, 35), nullptr, "planes");
    }
    // boreholes only: the tracer traces only the pixels of their boxes
    {
        Scene scene;
        for (int k = 0; k < 3; ++k)
            scene.boreholes.push_back(
                sbrt_test::borehole_at(m, f.west + (5.5 + 15 * k) * f.ew_res(),
                                       f.south + (8.5 + 10 * k) * f.ns_res()));
        scene.borehole_radius = 0.4 * f.ew_res();
        scene.draw_model = false;
        const Renderer renderer(m, 2.0, scene, kernel_shading(3, 0), {2, true, 4});
        expect_as_reference(renderer, view(renderer.tracer(), 10, 40, 1.5), nullptr,
                            "boreholes");
        const Renderer face(m, 2.0, scene, Shading{}, {2, true, 4});
        expect_as_reference(face, view(face.tracer(), 10, 40, 1.5), nullptr, "boreholes");
    }
}

TEST(Renderer, AnotherRowTracerTracesEachRowOnceWithFaceNormals)
{
    const Model m = sbrt_test::geology(30, 40, 24);
    const Renderer renderer(m, 1.5, Scene{}, Shading{}, {2, true, 13});
    const Camera camera = view(renderer.tracer(), 300, 40);
    CountingRows rows(renderer.tracer(), camera);
    expect_as_reference(renderer, camera, &rows, "row tracer");
    EXPECT_EQ(rows.rows_traced, camera.rows());
}

TEST(Renderer, OnlyTheOutputsAskedForAreStored)
{
    const Model m = sbrt_test::geology(30, 40, 24);
    const Renderer renderer(m, 1.5, Scene{}, Shading{}, {2, true, 10});
    const Camera camera = view(renderer.tracer(), 300, 40);
    int bands = 0, next_row = 0;
    renderer.render(camera, {false, true, false}, [&](const Band &band) {
        EXPECT_EQ(band.first_row, next_row); // in order, none missing
        next_row += band.rows;
        EXPECT_FALSE(band.rgb.empty());
        EXPECT_EQ(band.rgb.stride(), size_t(band.cols) * 3);
        EXPECT_TRUE(band.material.empty());
        EXPECT_EQ(band.elevation.stride(), size_t(band.cols));
        EXPECT_TRUE(band.depth.empty());
        ++bands;
    });
    EXPECT_EQ(next_row, camera.rows());
    EXPECT_EQ(bands, (camera.rows() + 9) / 10);
}

TEST(Renderer, ExceptionsOfWorkersAndOfTheSinkReachTheCaller)
{
    // a worker thread's exception, not std::terminate
    std::atomic<int> done{0};
    EXPECT_THROW(for_each_row(0, 1000, 4,
                              [&](int row) {
                                  if (row == 500)
                                      fail("row ", row);
                                  ++done;
                              }),
                 Error);
    EXPECT_LT(done.load(), 1000);
    // a row tracer that fails half way, and a sink that fails
    const Model m = sbrt_test::geology(30, 40, 24);
    const Renderer renderer(m, 1.5, Scene{}, Shading{}, {2, true, 4});
    const Camera camera = view(renderer.tracer(), 300, 40, 2.2, 61, 99);
    struct Failing : RowTracer {
        void trace_rows(int first, int count, Hit *out) override
        {
            if (first >= 20)
                fail("the GPU is gone");
            std::fill(out, out + size_t(count) * 99, Hit()); // rows of 99 pixels
        }
    } failing;
    EXPECT_THROW(renderer.render(camera, {}, [](const Band &) {}, &failing), Error);
    int taken = 0;
    EXPECT_THROW(renderer.render(camera, {},
                                 [&](const Band &band) {
                                     ++taken;
                                     if (band.first_row >= 8)
                                         fail("disk full");
                                 }),
                 Error);
    EXPECT_LE(taken, 5);
}
