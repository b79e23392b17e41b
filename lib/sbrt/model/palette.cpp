/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The default palette
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/palette.hpp"

#include <cmath>

namespace sbrt {

namespace {

// Greedy farthest-point sequence in CIEDE2000 (util/ciede2000.hpp): from
// the sRGB grid of step 15 with L* in [38, 88] (neither lost in shadow nor
// washed out by light), each entry the candidate farthest from black,
// white, mid grey (background, text, EMPTY) and every entry before it. So
// every prefix keeps its distance: the first 2 entries are 35 apart, the
// first 10 at least 26.6, all 30 at least 15.9.
constexpr uint8_t TABLE[PALETTE_SIZE][3] = {
    {105, 0, 255},   {0, 210, 0},     {255, 165, 0},   {255, 135, 255},
    {195, 0, 0},     {0, 105, 0},     {255, 135, 120}, {0, 195, 255},
    {210, 0, 120},   {120, 90, 0},    {45, 120, 225},  {0, 240, 210},
    {0, 105, 105},   {150, 150, 0},   {225, 225, 150}, {105, 90, 135},
    {180, 195, 255}, {90, 150, 105},  {195, 105, 30},  {195, 165, 180},
    {135, 90, 90},   {195, 165, 135}, {165, 195, 195}, {150, 105, 255},
    {0, 165, 165},   {255, 0, 75},    {255, 120, 165}, {90, 105, 75},
    {135, 135, 180}, {225, 45, 210},
};

} // namespace

std::array<uint8_t, 3> palette_color(size_t k)
{
    if (k < PALETTE_SIZE)
        return {TABLE[k][0], TABLE[k][1], TABLE[k][2]};
    // golden-angle hues: neighbouring entries get distinct colours
    const double h = std::fmod(double(k) * 137.508, 360.0) / 60.0;
    const double x = 1 - std::fabs(std::fmod(h, 2.0) - 1);
    const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x},
                              {0, x, 1}, {x, 0, 1}, {1, 0, x}};
    const double *c = rgb[int(h) % 6];
    return {uint8_t(60 + 180 * c[0]), uint8_t(60 + 180 * c[1]),
            uint8_t(60 + 180 * c[2])};
}

} // namespace sbrt
