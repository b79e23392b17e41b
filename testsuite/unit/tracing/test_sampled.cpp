/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The sampled method (fixed steps, adaptive) against the exact
 *            tracer: it converges as the step shrinks, its first solid
 *            sample lies at most one step behind the exact hit
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tracing/cpu_tracing.hpp"
#include "gpu_compare.hpp"
#include "tracing/sampled_tracer.hpp"

using namespace sbrt;

namespace {

struct Errors {
    size_t pixels = 0, wrong_material = 0;
    /// same material, but the sample lies more than a step behind the
    /// exact hit (the steps jumped over a corner of the surface)
    size_t far_behind = 0;
    double least_lag = INFINITY; ///< sampled t - exact t, in steps
};

Errors errors(const Tracer &tracer, const Camera &camera, const Sampling &s)
{
    const HitImage exact = trace_image(tracer, camera, 2);
    const HitImage sampled = sample_image(tracer, camera, s, 2);
    const double step_t = (s.fine_step > 0 ? s.fine_step : s.step) /
                          glm::length(tracer.frame().local_direction_from_exaggerated({0, 0, 1}));
    Errors e;
    e.pixels = exact.size();
    for (size_t i = 0; i < exact.size(); ++i) {
        if (exact[i].material != sampled[i].material) {
            ++e.wrong_material;
            continue;
        }
        if (!exact[i].is_hit())
            continue;
        const double lag = (sampled[i].t - exact[i].t) / step_t;
        e.far_behind += lag > 1 + 1e-9;
        e.least_lag = std::min(e.least_lag, lag);
    }
    return e;
}

} // namespace

TEST(SampledTracer, ConvergesToTheExactImageAsTheStepShrinks)
{
    // cubic voxels: a step of one cell is one voxel along every axis
    const Model m = sbrt_test::geology(40, 60, 30, {0, 0, 10, 10, 0});
    const Tracer tracer(m, 1.0);
    const Camera camera = Camera::perspective(
        tracer.frame().centre() + glm::dvec3(500, -700, 500), tracer.frame().centre(), 40, 90, 120);
    size_t previous = SIZE_MAX;
    for (double step : {1.0, 0.25, 1.0 / 16}) {
        const Errors e = errors(tracer, camera, {step, 0});
        EXPECT_LT(e.wrong_material, previous) << step;
        previous = e.wrong_material;
        // the first solid sample never lies in front of the surface, and
        // almost always within one step behind it
        EXPECT_GE(e.least_lag, -1e-9) << step;
        EXPECT_LT(e.far_behind, e.pixels / 100) << step;
    }
    EXPECT_LT(previous, size_t(0.02 * 90 * 120));
    // adaptive: coarse steps of a cell, fine ones of 1/16: as the fine
    // step alone where both found the surface
    const Errors adaptive = errors(tracer, camera, {1.0, 1.0 / 16});
    EXPECT_GE(adaptive.least_lag, -1e-9);
    EXPECT_LT(adaptive.far_behind, adaptive.pixels / 100);
    EXPECT_LT(adaptive.wrong_material, size_t(0.05 * 90 * 120));
}

TEST(SampledTracer, BadStepIsAnError)
{
    const Model m = sbrt_test::geology(8, 8, 8);
    const Tracer tracer(m, 1.0);
    EXPECT_THROW(sample_ray(tracer, {{0, 0, 1e4}, {0, 0, -1}}, {0, 0}), Error);
}
