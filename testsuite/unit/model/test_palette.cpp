/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The default palette keeps its stated CIEDE2000 distance for
 *            every class count up to 30; own colours win (issue 31)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "model/material_table.hpp"
#include "model/palette.hpp"
#include "util/ciede2000.hpp"

using namespace sbrt;

TEST(Palette, NearestPairMeetsTheStatedDistanceFor2To30Classes)
{
    for (size_t n = 2; n <= PALETTE_SIZE; ++n) {
        double nearest = 1e9;
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; j < i; ++j)
                nearest = std::min(nearest, ciede2000(palette_color(i), palette_color(j)));
        EXPECT_GE(nearest, PALETTE_MIN_DE00) << n << " classes";
    }
}

TEST(Palette, Issue31MaterialsWithoutColoursGetDistinctEntries)
{
    // lithoclasses 1-9 as a GeoTOP file meets them: 3 and 5 got the same
    // green from the golden-angle hues
    std::vector<Material> materials(10);
    for (int i = 1; i < 10; ++i)
        materials[size_t(i)].id = i;
    for (uint32_t a = 1; a < 10; ++a)
        for (uint32_t b = 1; b < a; ++b)
            EXPECT_GE(ciede2000(material_color(materials, a), material_color(materials, b)),
                      PALETTE_MIN_DE00)
                << "classes " << a << " and " << b;
    materials[3].has_color = true;
    materials[3].red = 1;
    materials[3].green = 2;
    materials[3].blue = 3;
    EXPECT_EQ(material_color(materials, 3), (std::array<uint8_t, 3>{1, 2, 3}));
    EXPECT_EQ(material_color(materials, 4), palette_color(3));
    // beyond the table: still a colour, not a crash
    const auto far = palette_color(40000);
    EXPECT_GE(int(far[0]) + far[1] + far[2], 60 * 3);
}
