/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Column logs (measure/column_log) against references computed
 *            voxel by voxel (voxel models with holes, overhangs, caves) and
 *            from the horizons (continuous tops), at UTM-size coordinates
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "builders/horizon_builder.hpp"
#include "measure/column_log.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

/// A log entry as the reference knows it: class id (NULL_CLASS: a gap)
/// and map heights.
struct RefEntry {
    int32_t id;
    double top, bottom;
};

/// The frame of random_voxels moved to UTM-size coordinates (zone 31
/// north, the Netherlands): 25 m cells, 0.5 m voxels from -50 m.
sbrt_test::Voxels utm_voxels(unsigned seed, int rows, int cols, int depths)
{
    sbrt_test::Voxels v = sbrt_test::random_voxels(seed, rows, cols, depths);
    v.frame.west = 500000;
    v.frame.east = 500000 + cols * 25.0;
    v.frame.north = 5800000 + rows * 25.0;
    v.frame.south = 5800000;
    v.frame.bottom = -50;
    v.frame.top = -50 + depths * 0.5;
    return v;
}

/// The log of cell (row, col) read voxel by voxel from the top down: runs
/// of one class are layers, null runs between two layers are gaps, null
/// above the highest and below the lowest layer is no entry.
std::vector<RefEntry> reference_log(const sbrt_test::Voxels &v, int row, int col)
{
    const Frame &f = v.frame;
    const double tb = (f.top - f.bottom) / f.depths;
    auto at = [&](int z) { return v.classes[(size_t(z) * f.rows + row) * f.cols + col]; };
    std::vector<RefEntry> log;
    for (int z = f.depths - 1; z >= 0; --z) {
        const int32_t id = at(z);
        if (!log.empty() && log.back().id == id)
            log.back().bottom = f.bottom + z * tb; // the run goes on down
        else if (id != NULL_CLASS || !log.empty())
            log.push_back({id, f.bottom + (z + 1) * tb, f.bottom + z * tb});
    }
    if (!log.empty() && log.back().id == NULL_CLASS)
        log.pop_back(); // below the lowest layer
    return log;
}

/// Every cell's log of `m` equals the voxel reference: class, both heights
/// exactly (voxel tops are exact small integers in local units).
void expect_logs_match_voxels(const Model &m, const sbrt_test::Voxels &v, unsigned seed)
{
    for (int row = 0; row < v.frame.rows; ++row)
        for (int col = 0; col < v.frame.cols; ++col) {
            const ColumnLog log = column_log(m, {row, col});
            const std::vector<RefEntry> ref = reference_log(v, row, col);
            ASSERT_EQ(log.entries.size(), ref.size())
                << "seed " << seed << " row " << row << " col " << col;
            EXPECT_EQ(log.is_empty(), ref.empty());
            for (size_t k = 0; k < ref.size(); ++k) {
                const LogEntry &e = log.entries[k];
                EXPECT_EQ(m.materials()[e.material].id, ref[k].id)
                    << "seed " << seed << " row " << row << " col " << col << " entry " << k;
                EXPECT_EQ(e.is_gap(), ref[k].id == NULL_CLASS);
                EXPECT_EQ(e.top, ref[k].top) << "row " << row << " col " << col << " entry " << k;
                EXPECT_EQ(e.bottom, ref[k].bottom)
                    << "row " << row << " col " << col << " entry " << k;
                EXPECT_EQ(e.thickness(), ref[k].top - ref[k].bottom);
            }
        }
}

} // namespace

TEST(ColumnLog, RandomVoxelColumnsWithCavesAndOverhangsAtUtmCoordinates)
{
    // random runs of 12 classes and nulls: caves (null between layers),
    // overhangs (null at the bottom), air, whole null columns (holes)
    for (unsigned seed = 1; seed <= 12; ++seed) {
        const auto v = utm_voxels(seed, 3 + seed % 5, 2 + seed % 4, 1 + int(seed * 7 % 41));
        const Model m = sbrt_test::build_model(v);
        ASSERT_TRUE(m.intervals().is_compact());
        expect_logs_match_voxels(m, v, seed);
        // the same intervals held wide (8 bytes, as mapped v1 files)
        expect_logs_match_voxels(sbrt_test::widened(m), v, seed);
    }
}

TEST(ColumnLog, HandMadeColumnsHoleOverhangCave)
{
    // 1 x 4 cells, 6 depths of 0.5 m from -50 m (bottom up per column):
    //   col 0: null x 6                 -> a hole: empty
    //   col 1: null, null, 3, 3, 7, null -> overhang: 7 over 3, nothing
    //          below -49 (no gap entry)
    //   col 2: 3, null, null, 7, 7, 7    -> a cave of 1 m between 7 and 3
    //   col 3: 5 x 6                     -> one layer up to the frame's top
    sbrt_test::Voxels v = utm_voxels(1, 1, 4, 6);
    const int32_t N = NULL_CLASS;
    const int32_t columns[4][6] = {
        {N, N, N, N, N, N}, {N, N, 3, 3, 7, N}, {3, N, N, 7, 7, 7}, {5, 5, 5, 5, 5, 5}};
    for (int z = 0; z < 6; ++z)
        for (int c = 0; c < 4; ++c)
            v.classes[size_t(z) * 4 + size_t(c)] = columns[c][z];
    const Model m = sbrt_test::build_model(v);
    auto id = [&](const LogEntry &e) { return m.materials()[e.material].id; };

    EXPECT_TRUE(column_log(m, {0, 0}).is_empty());

    const ColumnLog overhang = column_log(m, {0, 1});
    ASSERT_EQ(overhang.entries.size(), 2u);
    EXPECT_EQ(id(overhang.entries[0]), 7);
    EXPECT_EQ(overhang.entries[0].top, -47.5);
    EXPECT_EQ(overhang.entries[0].bottom, -48.0);
    EXPECT_EQ(id(overhang.entries[1]), 3);
    EXPECT_EQ(overhang.entries[1].bottom, -49.0);

    const ColumnLog cave = column_log(m, {0, 2});
    ASSERT_EQ(cave.entries.size(), 3u);
    EXPECT_EQ(cave.layer_count(), 2u);
    EXPECT_EQ(id(cave.entries[0]), 7);
    EXPECT_EQ(cave.entries[0].top, -47.0);
    EXPECT_EQ(cave.entries[0].thickness(), 1.5);
    EXPECT_TRUE(cave.entries[1].is_gap());
    EXPECT_EQ(cave.entries[1].top, -48.5);
    EXPECT_EQ(cave.entries[1].bottom, -49.5);
    EXPECT_EQ(id(cave.entries[2]), 3);
    EXPECT_EQ(cave.entries[2].bottom, -50.0);

    const ColumnLog full = column_log(m, {0, 3});
    ASSERT_EQ(full.entries.size(), 1u);
    EXPECT_EQ(full.entries[0].top, -47.0);
    EXPECT_EQ(full.entries[0].bottom, -50.0);
}

TEST(ColumnLog, HorizonModelKeepsContinuousTopsAtUtmCoordinates)
{
    // 3 units (ids 11, 12, 13, top to bottom) over 1 m voxels from -100 m;
    // tops drawn at random between voxel levels, unit 12 absent (NaN) in
    // some columns, the base above the frame's bottom in others
    Frame f;
    f.rows = 6;
    f.cols = 7;
    f.depths = 120;
    f.west = 480000;
    f.east = 480000 + 7 * 100.0;
    f.south = 5790000;
    f.north = 5790000 + 6 * 100.0;
    f.bottom = -100;
    f.top = 20;
    std::vector<Material> units(3);
    for (int i = 0; i < 3; ++i)
        units[size_t(i)].id = 11 + i;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    const size_t cells = size_t(f.rows) * size_t(f.cols);
    // horizons[i][cell], bases[cell]: non-crossing, top to bottom
    std::vector<std::vector<double>> horizons(3, std::vector<double>(cells));
    std::vector<double> bases(cells);
    for (size_t c = 0; c < cells; ++c) {
        horizons[0][c] = 10 + 9 * unit(rng);
        horizons[1][c] = c % 3 == 0 ? NAN : -20 - 30 * unit(rng);
        horizons[2][c] = -55 - 20 * unit(rng);
        bases[c] = c % 4 == 0 ? -80.25 - 10 * unit(rng) : NAN;
    }
    HorizonStackBuilder builder(f, units);
    for (int r = 0; r < f.rows; ++r) {
        const size_t first = size_t(r) * size_t(f.cols);
        builder.add_row({&horizons[0][first], &horizons[1][first], &horizons[2][first]},
                        &bases[first]);
    }
    const Model m = builder.finish();
    ASSERT_FALSE(m.intervals().is_compact());
    // float32 local tops: within 2^-23 of 120 voxels of 1 m, far below a
    // voxel (a rounding to levels would be off by up to 0.5 m)
    const double tolerance = 120 * std::ldexp(1.0, -23);
    int continuous = 0;
    for (int r = 0; r < f.rows; ++r)
        for (int c = 0; c < f.cols; ++c) {
            const size_t cell = size_t(r) * size_t(f.cols) + size_t(c);
            std::vector<RefEntry> ref;
            for (int i = 0; i < 3; ++i)
                if (!std::isnan(horizons[size_t(i)][cell]))
                    ref.push_back({11 + i, horizons[size_t(i)][cell], 0});
            for (size_t k = 0; k < ref.size(); ++k)
                ref[k].bottom = k + 1 < ref.size() ? ref[k + 1].top
                                : std::isnan(bases[cell]) ? f.bottom
                                                          : bases[cell];
            const ColumnLog log = column_log(m, {r, c});
            ASSERT_EQ(log.entries.size(), ref.size()) << "row " << r << " col " << c;
            for (size_t k = 0; k < ref.size(); ++k) {
                const LogEntry &e = log.entries[k];
                EXPECT_EQ(m.materials()[e.material].id, ref[k].id);
                EXPECT_NEAR(e.top, ref[k].top, tolerance) << "row " << r << " col " << c;
                EXPECT_NEAR(e.bottom, ref[k].bottom, tolerance) << "row " << r << " col " << c;
                continuous += std::fabs(e.top - std::round(e.top)) > 0.01;
            }
        }
    EXPECT_GT(continuous, 50) << "tops should lie between voxel levels";
}

TEST(ColumnLog, CellOfPointAtUtmCoordinates)
{
    const auto v = utm_voxels(3, 40, 30, 4);
    const Frame &f = v.frame;
    for (int row = 0; row < f.rows; ++row)
        for (int col = 0; col < f.cols; ++col) {
            // the centre and the north-west corner belong to the cell
            const double x = f.west + (col + 0.5) * 25.0, y = f.north - (row + 0.5) * 25.0;
            const auto centre = cell_of_point(f, x, y);
            ASSERT_TRUE(centre.has_value());
            EXPECT_EQ(centre->row, row);
            EXPECT_EQ(centre->col, col);
            const auto corner = cell_of_point(f, f.west + col * 25.0, f.north - row * 25.0);
            ASSERT_TRUE(corner.has_value());
            EXPECT_EQ(corner->row, row);
            EXPECT_EQ(corner->col, col);
        }
    // outside: beyond each edge (east and south edges themselves, as
    // GRASS counts them), and coordinates that are no numbers
    const double xm = (f.west + f.east) / 2, ym = (f.south + f.north) / 2;
    EXPECT_FALSE(cell_of_point(f, f.west - 0.001, ym));
    EXPECT_FALSE(cell_of_point(f, f.east, ym));
    EXPECT_FALSE(cell_of_point(f, xm, f.south));
    EXPECT_FALSE(cell_of_point(f, xm, f.north + 0.001));
    EXPECT_FALSE(cell_of_point(f, NAN, ym));
    EXPECT_FALSE(cell_of_point(f, xm, INFINITY));
    EXPECT_TRUE(cell_of_point(f, f.east - 0.001, f.south + 0.001));
}

TEST(ColumnLog, CellOutsideTheFrameThrows)
{
    const Model m = sbrt_test::build_model(utm_voxels(2, 3, 4, 5));
    EXPECT_THROW(column_log(m, {3, 0}), Error);
    EXPECT_THROW(column_log(m, {0, -1}), Error);
}
