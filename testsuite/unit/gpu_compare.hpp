/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   What the GPU tests share: a GL context, the agreement of GPU
 *            hits with the CPU tracer's, a folded and faulted test model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TEST_GPU_COMPARE_HPP
#define SBRT_TEST_GPU_COMPARE_HPP

#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "util/error.hpp"
#include "gpu_renderer.hpp"
#include "gpu_tracer.hpp"
#include "renderer.hpp"
#include "test_support.hpp"

namespace sbrt_test {

using namespace sbrt;

/// One GL context for every test of a suite (each backend once).
inline std::unique_ptr<sbrt_gl::GlContext> make_context(const char *backend)
{
    try {
        return sbrt_gl::create_gl_context(backend);
    }
    catch (const Error &e) {
        ADD_FAILURE() << "no GL context (" << backend << "): " << e.what();
        return nullptr;
    }
}

/// \brief The GL a GPU test runs on and the branches of the GPU path it
/// takes: the ones that GL calls for (llvmpipe: bands written in place, a
/// loop budget), or a GPU's forced (bands staged in GPU memory and copied
/// by the GPU, no loop budget), so that llvmpipe runs them too.
struct GpuVariant {
    const char *backend = "egl";
    GpuLayout layout = GpuLayout::ssbo;
    sbrt_gl::BandStaging bands = sbrt_gl::BandStaging::automatic;
    bool unbounded = false;

    sbrt_gl::GpuOptions options() const
    {
        sbrt_gl::GpuOptions o;
        o.layout = layout;
        o.bands = bands;
        if (unbounded)
            o.loop_budget = sbrt_gl::UNBOUNDED_LOOP_BUDGET;
        return o;
    }
    /// The same with a loop budget of `budget`.
    sbrt_gl::GpuOptions options(uint32_t budget) const
    {
        sbrt_gl::GpuOptions o = options();
        o.loop_budget = budget;
        return o;
    }
    /// e.g. egl_ssbo, egl_textures_staged_unbounded
    std::string name() const
    {
        std::string n = std::string(backend) + "_" + gpu_layout_name(layout);
        if (bands == sbrt_gl::BandStaging::staged)
            n += "_staged";
        if (bands == sbrt_gl::BandStaging::direct)
            n += "_direct";
        return unbounded ? n + "_unbounded" : n;
    }
};

/// Every GL backend in both layouts as the GL calls for, then on EGL
/// (llvmpipe in CI) a GPU's branches: staged bands, no loop budget, both.
inline std::vector<GpuVariant> gpu_variants()
{
    using sbrt_gl::BandStaging;
    std::vector<GpuVariant> out;
    std::vector<const char *> backends = {"egl"};
#ifdef SBRT_HAVE_OSMESA
    backends.push_back("osmesa");
#endif
    for (const char *backend : backends)
        for (GpuLayout layout : {GpuLayout::ssbo, GpuLayout::textures})
            out.push_back({backend, layout});
    out.push_back({"egl", GpuLayout::ssbo, BandStaging::staged, false});
    out.push_back({"egl", GpuLayout::ssbo, BandStaging::automatic, true});
    out.push_back({"egl", GpuLayout::textures, BandStaging::staged, true});
    return out;
}

/// \brief A test run on each GL variant of its suite: a context of the
/// variant's backend made for each test (a failure where none).
class GpuVariantTest : public ::testing::TestWithParam<GpuVariant> {
protected:
    void SetUp() override
    {
        context_ = make_context(GetParam().backend);
        if (!context_)
            GTEST_FAIL();
    }
    GpuLayout layout() const { return GetParam().layout; }
    sbrt_gl::GpuOptions options() const { return GetParam().options(); }
    std::unique_ptr<sbrt_gl::GlContext> context_;
};

/// How GoogleTest prints a variant.
inline void PrintTo(const GpuVariant &variant, std::ostream *out) { *out << variant.name(); }

/// The test name of a variant parameter.
inline std::string variant_name(const ::testing::TestParamInfo<GpuVariant> &info)
{
    return info.param.name();
}

/// Pixels agree when both rays hit the same material at depths within
/// `depth_tolerance` map units, or both miss.
struct Agreement {
    size_t pixels = 0, hits = 0, same_material = 0, agreeing = 0;
};

/// GPU hits against the CPU tracer's on one camera.
inline Agreement compare(sbrt_gl::GpuTracer &gpu, const Tracer &tracer,
                         const Camera &camera, double depth_tolerance,
                  size_t *over_budget, uint32_t budget)
{
    const HitImage want = trace_image(tracer, camera, 2);
    const HitImage got = gpu.trace_image(camera, 2, budget);
    if (over_budget)
        *over_budget = gpu.stats().over_budget;
    Agreement a;
    a.pixels = want.size();
    for (size_t i = 0; i < want.size(); ++i) {
        a.hits += want[i].is_hit();
        if (want[i].material != got[i].material)
            continue;
        ++a.same_material;
        a.agreeing += !want[i].is_hit() ||
                      std::fabs(want[i].t - got[i].t) < depth_tolerance;
    }
    return a;
}

/// The same with the tolerance: 1e-4 of the model's size; by
/// default the tracer's loop budget (its options').
inline Agreement compare(sbrt_gl::GpuTracer &gpu, const Tracer &tracer,
                         const Camera &camera, size_t *over_budget = nullptr,
                         std::optional<uint32_t> budget = std::nullopt)
{
    return compare(gpu, tracer, camera, 1e-4 * 2 * tracer.frame().radius(), over_budget,
                   budget.value_or(gpu.loop_budget()));
}

/// Where and how large the cells of geology() are.
struct Placement {
    double west = 612000.5, south = 4312000.25; // UTM-sized: float would lose them
    double cell = 25, tb = 4, bottom = -300;
};

/// The frame of rows x cols cells x depths levels placed at `at`.
inline Frame placed_frame(int rows, int cols, int depths, Placement at = {})
{
    Frame f;
    f.rows = rows;
    f.cols = cols;
    f.depths = depths;
    f.west = at.west;
    f.east = at.west + cols * at.cell;
    f.south = at.south;
    f.north = at.south + rows * at.cell;
    f.bottom = at.bottom;
    f.top = at.bottom + depths * at.tb;
    return f;
}

/// Every pixel of `got` against `want`: classes equal, colours within a
/// level, elevations and depths within `tolerance` (NaN alike).
inline void expect_images_agree(const Image &want, const Image &got, double tolerance,
                         const std::string &what)
{
    ASSERT_EQ(got.rgb.size(), want.rgb.size()) << what;
    size_t classes = 0, colours = 0, far = 0;
    for (size_t i = 0; i < want.material.size(); ++i) {
        classes += got.material[i] != want.material[i];
        for (int k = 0; k < 3; ++k)
            colours += std::abs(int(got.rgb[i * 3 + k]) - int(want.rgb[i * 3 + k])) > 1;
        const bool missed = want.material[i] == NULL_CLASS;
        if (got.material[i] != want.material[i])
            continue;
        if (missed)
            far += !(std::isnan(got.elevation[i]) && std::isnan(got.depth[i]));
        else
            far += !(std::fabs(got.elevation[i] - want.elevation[i]) <= tolerance &&
                     std::fabs(got.depth[i] - want.depth[i]) <= tolerance);
    }
    const size_t n = want.material.size();
    EXPECT_LE(classes, n / 500 + 1) << what;
    EXPECT_LE(colours, n / 200 + 3 * classes) << what;
    EXPECT_EQ(far, 0u) << what;
}

/// A layered model with folds, a cave and a hole through it.
inline Model geology(int rows, int cols, int depths, Placement at = {})
{
    Voxels v;
    v.frame = placed_frame(rows, cols, depths, at);
    v.classes.assign(v.frame.voxels(), NULL_CLASS);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const double surface =
                depths * (0.7 + 0.2 * std::sin(c * 0.21) * std::cos(r * 0.17));
            for (int z = 0; z < depths && z < surface; ++z) {
                const double fold = z + 3 * std::sin((c + 2 * r) * 0.15);
                int32_t id = 1 + int(std::floor(fold / 3)) % 7;
                const bool cave = std::hypot(c - cols / 2.0, z - depths / 3.0) < 4 &&
                                  r > rows / 4;
                const bool hole = std::abs(r - rows / 3) < 2 && std::abs(c - cols / 4) < 2;
                if (cave || hole)
                    id = NULL_CLASS;
                v.classes[(size_t(z) * rows + r) * cols + c] = id;
            }
        }
    return build_model(v);
}

/// The agreement of the issue: >= 99.9 % of the pixels see the same
/// material at the same depth (within 1e-4 of the model's size).
inline void expect_agreement(const Agreement &a, const char *view)
{
    EXPECT_GE(a.agreeing, a.pixels - a.pixels / 1000)
        << view << ": " << a.agreeing << " of " << a.pixels;
}

/// The streamed render with the GPU shading against the CPU's: colour
/// levels within 1, classes equal but on a share of edge pixels,
/// elevation and depth within float rounding of the model's size but on
/// `far_allowed` pixels (a ray along a cell's edge, in float, may meet the
/// material of the cell beside); more than one pixel in `hits_in` a hit.
inline void expect_gpu_shading_as_cpu(const sbrt_gl::GlContext &context,
                                      const sbrt_gl::GpuOptions &options,
                                      const Renderer &renderer, const Camera &camera,
                                      const std::string &what, size_t far_allowed = 0,
                                      size_t hits_in = 10)
{
    sbrt_gl::GpuRenderer on_gpu(context, renderer, options);
    const sbrt_gl::GpuTracer &gpu = on_gpu.gpu();
    const Outputs all{true, true, true};
    const Image want = renderer.render_image(camera, all);
    EXPECT_TRUE(on_gpu.shades_on_gpu(camera)) << what;
    const Image got = on_gpu.render_image(camera, all, 2);
    EXPECT_TRUE(gpu.shade_program() != 0 || gpu.kernel_program() != 0)
        << "the GPU did not shade: " << what;
    if (renderer.shading().normals == Normals::kernel) {
        EXPECT_NE(gpu.kernel_program(), 0u) << "kernel normals not found on the GPU: " << what;
    }
    const size_t n = want.material.size();
    size_t classes = 0, colours = 0, far = 0, hits = 0;
    const double tolerance = 2e-5 * 2 * renderer.tracer().frame().radius();
    for (size_t i = 0; i < n; ++i) {
        classes += got.material[i] != want.material[i];
        for (int k = 0; k < 3; ++k)
            colours += std::abs(int(got.rgb[i * 3 + k]) - int(want.rgb[i * 3 + k])) > 1;
        if (got.material[i] == want.material[i] && want.material[i] != NULL_CLASS) {
            ++hits;
            far += !(std::fabs(got.elevation[i] - want.elevation[i]) <= tolerance &&
                     std::fabs(got.depth[i] - want.depth[i]) <= tolerance);
        }
        else if (want.material[i] == NULL_CLASS && got.material[i] == NULL_CLASS) {
            far += !(std::isnan(got.elevation[i]) && std::isnan(got.depth[i]));
        }
    }
    // the GPU traced them (the host traces again only rays over its budget)
    EXPECT_LE(gpu.stats().over_budget, n / 100) << what;
    EXPECT_GT(hits, n / hits_in) << what;
    EXPECT_LE(classes, n / 500 + 1) << what;
    EXPECT_LE(colours, n / 200 + classes * 3) << what;
    EXPECT_LE(far, far_allowed) << what;
}


} // namespace sbrt_test

#endif
