/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The exaggeration a render gets without zexag= (issue 31, item
 *            3): its figures, and the default view of a GeoTOP-like
 *            model with it showing sides a quarter of the image high
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "frame/fitting_exaggeration.hpp"
#include "gpu_compare.hpp"
#include "scene/view.hpp"

using namespace sbrt;

TEST(FittingExaggeration, RoundsTheThicknessShareToATypedNumber)
{
    // 0.3 sqrt(6000 * 5000) / 35 = 46.9 -> 50
    EXPECT_EQ(fitting_exaggeration(6000, 5000, 35), 50);
    // 0.3 * 1900 / 156 = 3.65 -> 4 (the GeoTOP subset)
    EXPECT_EQ(fitting_exaggeration(1900, 1900, 156), 4);
    // national size: 265 x 300 km, 60 m thick: 1410 -> 1500
    EXPECT_EQ(fitting_exaggeration(265000, 300000, 60), 1500);
    // 0.3 * 1000 / 120 = 2.5
    EXPECT_EQ(fitting_exaggeration(1000, 1000, 120), 2.5);
    // thick enough already: never flattened
    EXPECT_EQ(fitting_exaggeration(1000, 1000, 300), 1);
    EXPECT_EQ(fitting_exaggeration(1000, 1000, 5000), 1);
    // nothing to fit
    EXPECT_EQ(fitting_exaggeration(1000, 1000, 0), 1);
    EXPECT_EQ(fitting_exaggeration(0, 1000, 10), 1);
    EXPECT_EQ(fitting_exaggeration(1e308, 1e308, 1e-300), 1);
}

namespace {

/// The tallest run of side-wall pixels (normal near horizontal) in an
/// image column of the default view of `t`, every `step`-th column.
int tallest_side(const Tracer &t, int rows, int cols, int step)
{
    const Camera camera = view_camera(View{}, t.model(), t.frame(), rows, cols);
    int tallest = 0;
    for (int c = 0; c < cols; c += step) {
        int run = 0;
        for (int r = 0; r < rows; ++r) {
            const Hit h = t.trace(camera.ray(r, c));
            run = h.is_hit() && std::fabs(h.normal.z) < 0.5f ? run + 1 : 0;
            tallest = std::max(tallest, run);
        }
    }
    return tallest;
}

} // namespace

TEST(FittingExaggeration, DefaultViewOfAGeotopLikeModelShowsItsSides)
{
    // 60 x 50 cells of 100 m, 80 levels of 0.5 m, the surface at about
    // 0.7 of the height: GeoTOP's proportions
    sbrt_test::Placement geotop;
    geotop.cell = 100;
    geotop.tb = 0.5;
    geotop.bottom = -50;
    const Model m = sbrt_test::geology(50, 60, 80, geotop);
    const double zexag = fitting_exaggeration(m);
    EXPECT_GE(zexag, 30);
    EXPECT_LE(zexag, 80);
    const int rows = 500, cols = 800;
    EXPECT_GE(tallest_side(Tracer(m, zexag), rows, cols, 2), rows / 4) << "zexag " << zexag;
    // at zexag=1 the same view is a sheet
    EXPECT_LT(tallest_side(Tracer(m, 1.0), rows, cols, 4), rows / 20);
}
