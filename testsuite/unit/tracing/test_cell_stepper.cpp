/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The tracer's cell walk (CellStepper) against the cells a ray
 *            crosses found by sampling the ray densely (fixed seeds), and
 *            its jumps, ends and axis-parallel rays
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tracing/cell_stepper.hpp"

using namespace sbrt;

namespace {

struct Stretch {
    int x, y;
    double t_in, t_out;
    Face face;
};

/// Every stretch of a walk from t_near to t_far.
std::vector<Stretch> walk(double ox, double oy, double dx, double dy, double t_near,
                          double t_far, int cols, int rows)
{
    std::vector<Stretch> out;
    CellStepper cells(ox, oy, dx, dy, 1 / dx, 1 / dy, t_near, t_far, Face::none, cols, rows);
    for (int guard = 0; !cells.done() && guard < 10 * (cols + rows); ++guard) {
        out.push_back({cells.x(), cells.y(), cells.t_in(), cells.t_out(), cells.face()});
        cells.next();
    }
    return out;
}

} // namespace

TEST(CellStepper, CrossesTheCellsADenseSampleOfTheRayFinds)
{
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> pos(-3, 23), dir(-1, 1);
    const int cols = 17, rows = 11;
    int walked = 0;
    for (int k = 0; k < 400; ++k) {
        const double ox = pos(rng), oy = pos(rng), dx = dir(rng), dy = dir(rng);
        // the part of the ray over the grid
        double t_near = 0, t_far = INFINITY;
        const double inv_x = 1 / dx, inv_y = 1 / dy;
        double tx0 = -ox * inv_x, tx1 = (cols - ox) * inv_x;
        double ty0 = -oy * inv_y, ty1 = (rows - oy) * inv_y;
        t_near = std::max({t_near, std::min(tx0, tx1), std::min(ty0, ty1)});
        t_far = std::min({t_far, std::max(tx0, tx1), std::max(ty0, ty1)});
        if (!(t_near < t_far))
            continue;
        ++walked;
        const std::vector<Stretch> stretches = walk(ox, oy, dx, dy, t_near, t_far, cols, rows);
        ASSERT_FALSE(stretches.empty());
        // the stretches tile [t_near, t_far] in order, each in its cell
        EXPECT_EQ(stretches.front().t_in, t_near);
        EXPECT_NEAR(stretches.back().t_out, t_far, 1e-9);
        std::set<std::pair<int, int>> walked_cells;
        for (size_t i = 0; i < stretches.size(); ++i) {
            const Stretch &s = stretches[i];
            walked_cells.insert({s.x, s.y});
            if (i > 0) {
                EXPECT_EQ(s.t_in, stretches[i - 1].t_out);
                EXPECT_EQ(std::abs(s.x - stretches[i - 1].x) + std::abs(s.y - stretches[i - 1].y), 1)
                    << "neighbours only";
                // entered through the wall it crossed
                const Face expected = s.x != stretches[i - 1].x
                                          ? (dx > 0 ? Face::west : Face::east)
                                          : (dy > 0 ? Face::south : Face::north);
                EXPECT_EQ(s.face, expected);
            }
            const double mid = (s.t_in + s.t_out) / 2;
            if (s.t_out - s.t_in > 1e-9) {
                EXPECT_EQ(int(std::floor(ox + mid * dx)), s.x);
                EXPECT_EQ(int(std::floor(oy + mid * dy)), s.y);
            }
        }
        // a dense sample of the ray finds no cell the walk missed
        for (int j = 1; j < 2000; ++j) {
            const double t = t_near + (t_far - t_near) * j / 2000;
            const int x = int(std::floor(ox + t * dx)), y = int(std::floor(oy + t * dy));
            if (x >= 0 && x < cols && y >= 0 && y < rows) {
                EXPECT_TRUE(walked_cells.count({x, y})) << "ray " << k << " missed cell " << x
                                                        << "," << y;
            }
        }
    }
    EXPECT_GT(walked, 100);
}

TEST(CellStepper, AxisParallelRaysNeverCrossTheOtherWalls)
{
    // along +x at y = 2.5: cells (0..9, 2), entered through their west walls
    const std::vector<Stretch> east = walk(-1, 2.5, 1, 0, 1, 11, 10, 5);
    ASSERT_EQ(east.size(), 10u);
    for (int x = 0; x < 10; ++x) {
        EXPECT_EQ(east[size_t(x)].x, x);
        EXPECT_EQ(east[size_t(x)].y, 2);
        EXPECT_EQ(east[size_t(x)].t_in, x == 0 ? 1.0 : x + 1.0);
        if (x > 0) {
            EXPECT_EQ(east[size_t(x)].face, Face::west);
        }
    }
    // along -y: north walls
    const std::vector<Stretch> south = walk(4.5, 5, 0, -1, 0, 5, 10, 5);
    ASSERT_EQ(south.size(), 5u);
    EXPECT_EQ(south[1].y, 3);
    EXPECT_EQ(south[1].face, Face::north);
    // straight down (no x, y motion): one cell for the whole stretch
    const std::vector<Stretch> down = walk(3.5, 1.5, 0, 0, 0, 7, 10, 5);
    ASSERT_EQ(down.size(), 1u);
    EXPECT_EQ(down[0].t_out, 7);
}

TEST(CellStepper, JumpsLandInTheCellGivenAndStopAtTheEnd)
{
    CellStepper cells(0.5, 0.5, 1, 0.25, 1, 4, 0, 30, Face::none, 32, 8);
    EXPECT_EQ(cells.x(), 0);
    cells.jump_to(16, 4, 15.5, Face::west);
    ASSERT_FALSE(cells.done());
    EXPECT_EQ(cells.x(), 16);
    EXPECT_EQ(cells.y(), 4);
    EXPECT_EQ(cells.t_in(), 15.5);
    EXPECT_EQ(cells.face(), Face::west);
    EXPECT_EQ(cells.t_out(), 16.5); // x = 17 at t = 16.5, before y = 5 at t = 17.5
    cells.next();
    EXPECT_EQ(cells.x(), 17);
    // a jump at or past t_far ends the walk, as one off the grid does
    CellStepper late(0.5, 0.5, 1, 0.25, 1, 4, 0, 10, Face::none, 32, 8);
    late.jump_to(12, 3, 10, Face::west);
    EXPECT_TRUE(late.done());
    CellStepper off(0.5, 0.5, 1, 0.25, 1, 4, 0, 30, Face::none, 32, 8);
    off.jump_to(32, 3, 20, Face::west);
    EXPECT_TRUE(off.done());
    // the walk ends at t_far, inside the grid
    const std::vector<Stretch> short_walk = walk(0.5, 0.5, 1, 0, 0, 2.25, 32, 8);
    ASSERT_EQ(short_walk.size(), 3u);
    EXPECT_EQ(short_walk.back().t_out, 2.25);
}
