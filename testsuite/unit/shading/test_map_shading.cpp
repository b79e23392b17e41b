/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   A top view is a map in its legend's colours (issue 51, item
 *            4): lit from straight above, an upward face shows its class's
 *            colour exactly whatever the ambient share; other views keep
 *            light=
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gpu_compare.hpp"
#include "shading/shading.hpp"

using namespace sbrt;
using sbrt_test::geology;

TEST(MapShading, TheLightOfATopViewIsStraightAbove)
{
    EXPECT_EQ(Shading::light_of_view(ViewKind::top, 315, 45), glm::dvec3(0, 0, 1));
    for (const ViewKind kind : {ViewKind::perspective, ViewKind::orthographic})
        EXPECT_EQ(Shading::light_of_view(kind, 315, 45), Shading::light_from(315, 45));
}

TEST(MapShading, ATopViewShowsEveryClassInItsLegendColour)
{
    const Model m = geology(30, 40, 20);
    const Tracer tracer(m, 1.0);
    const Camera camera = sbrt_test::top_camera(m.frame(), m.frame().top + 100);
    const HitImage hits = trace_image(tracer, camera, 1);
    for (const double ambient : {0.0, 0.35, 0.8}) {
        Shading shading;
        shading.light = Shading::light_of_view(ViewKind::top, 315, 45);
        shading.ambient = ambient;
        const Image image = shade(tracer, camera, hits, shading, 1);
        const PixelShader shader(m, shading);
        int tops = 0, off = 0;
        for (size_t i = 0; i < hits.size(); ++i) {
            if (!hits[i].is_hit())
                continue;
            ++tops;
            const auto legend = material_color(m, hits[i].material);
            const std::array<uint8_t, 3> rgb{image.rgb[3 * i], image.rgb[3 * i + 1],
                                             image.rgb[3 * i + 2]};
            off += rgb != legend;
            // the per-hit path (no table of lit faces) too
            Hit hit = hits[i];
            hit.normal = glm::normalize(glm::vec3(1e-9f, 0, 1));
            off += shader(hit) != legend;
        }
        EXPECT_GT(tops, 30 * 40 / 2) << ambient;
        EXPECT_EQ(off, 0) << "ambient " << ambient << ", of " << tops;
    }
    // the light of a 3D view (from the north-west, 45 degrees up) shades
    // the same tops at 81 %
    Shading lit;
    lit.light = Shading::light_of_view(ViewKind::perspective, 315, 45);
    const Image image = shade(tracer, camera, hits, lit, 1);
    int tops = 0, shaded = 0;
    for (size_t i = 0; i < hits.size(); ++i)
        if (hits[i].is_hit()) {
            const auto legend = material_color(m, hits[i].material);
            ++tops;
            shaded += image.rgb[3 * i] < legend[0] || image.rgb[3 * i + 1] < legend[1] ||
                      image.rgb[3 * i + 2] < legend[2];
        }
    EXPECT_EQ(shaded, tops);
}
