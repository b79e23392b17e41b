/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Volumes of classes and class sets, in the whole model, in a
 *            window and inside polygons with holes, against voxel counts
 *            times the voxel's volume and a point-in-polygon reference
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "builders/horizon_builder.hpp"
#include "measure/cell_zones.hpp"
#include "measure/volumes.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;
using sbrt_test::Voxels;

namespace {

struct Reference {
    uint64_t voxels = 0, cells = 0;
};

/// Voxels of the class ids `set` and the columns holding any, counted
/// voxel by voxel over the cells `counts` says count.
template <typename Counts>
Reference count_voxels(const Voxels &v, const std::set<int32_t> &set, Counts counts)
{
    Reference ref;
    for (uint64_t cell = 0; cell < v.frame.cells(); ++cell) {
        if (!counts(cell))
            continue;
        uint64_t n = 0;
        for (int z = 0; z < v.frame.depths; ++z)
            n += set.count(v.classes[size_t(z) * v.frame.cells() + cell]);
        ref.voxels += n;
        ref.cells += n > 0;
    }
    return ref;
}

double voxel_volume(const Frame &f) { return f.ns_res() * f.ew_res() * f.tb_res(); }

/// Even-odd point in polygon (the crossing test), the reference of a
/// cell centre inside an area.
bool inside(const Polygon &polygon, double x, double y)
{
    bool in = false;
    for (const auto &ring : polygon)
        for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
            if ((ring[i].y > y) != (ring[j].y > y) &&
                x < (ring[j].x - ring[i].x) * (y - ring[i].y) / (ring[j].y - ring[i].y) +
                        ring[i].x)
                in = !in;
    return in;
}

Voxels utm_voxels(unsigned seed)
{
    Voxels v = sbrt_test::random_voxels(seed, 23, 31, 40, 5);
    v.frame.north = 5800000 + 23 * 25.0;
    v.frame.south = 5800000;
    v.frame.west = 450000;
    v.frame.east = 450000 + 31 * 25.0;
    v.frame.bottom = -60;
    v.frame.top = -60 + 40 * 0.5;
    return v;
}

} // namespace

TEST(Volumes, EveryClassOfRandomModelsEqualsTheVoxelCount)
{
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const Voxels v = utm_voxels(seed);
        const Model m = sbrt_test::build_model(v);
        const std::vector<ClassSet> sets = every_class(m);
        const VolumeTable t = measure_volumes(m, sets, CellZones::whole(m.frame()), 3);
        ASSERT_EQ(t.sets(), m.materials().size() - 1);
        for (size_t s = 0; s < sets.size(); ++s) {
            const int32_t id = m.materials()[sets[s].materials()[0]].id;
            const Reference ref = count_voxels(v, {id}, [](uint64_t) { return true; });
            EXPECT_EQ(t.at(0, s).volume, double(ref.voxels) * voxel_volume(v.frame))
                << "seed " << seed << " class " << id;
            EXPECT_EQ(t.at(0, s).cells, ref.cells) << "seed " << seed << " class " << id;
        }
    }
}

TEST(Volumes, SetsCountACellOnceAndTheFiguresDoNotDependOnThreads)
{
    const Voxels v = utm_voxels(11);
    const Model m = sbrt_test::build_model(v);
    const std::set<int32_t> ids{-13, 8, 15};
    const std::vector<ClassSet> sets{ClassSet::named(m, {"-13", "8", "15"}),
                                     ClassSet::named(m, {"8"})};
    const CellZones whole = CellZones::whole(m.frame());
    const VolumeTable one = measure_volumes(m, sets, whole, 1);
    const VolumeTable many = measure_volumes(sbrt_test::widened(m), sets, whole, 4);
    const Reference ref = count_voxels(v, ids, [](uint64_t) { return true; });
    EXPECT_EQ(one.at(0, 0).volume, double(ref.voxels) * voxel_volume(v.frame));
    EXPECT_EQ(one.at(0, 0).cells, ref.cells);
    EXPECT_EQ(one.at(0, 0).thickness, double(ref.voxels) * v.frame.tb_res());
    for (size_t s = 0; s < 2; ++s) {
        EXPECT_EQ(one.at(0, s).volume, many.at(0, s).volume);
        EXPECT_EQ(one.at(0, s).cells, many.at(0, s).cells);
    }
}

TEST(Volumes, WindowCountsTheCellsWhoseCentreLiesInIt)
{
    const Voxels v = utm_voxels(5);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = m.frame();
    // a window cutting cells: centres inside are those of rows 3..14 and
    // columns 5..20 (edges at 40% and 60% of a cell)
    const GridWindow window{f.north - 2.6 * 25, f.north - 14.6 * 25, f.west + 20.6 * 25,
                            f.west + 4.6 * 25, 1, 1};
    const CellZones zones = CellZones::in_window(f, window);
    const VolumeTable t = measure_volumes(m, {ClassSet::named(m, {"1"})}, zones);
    const Reference ref = count_voxels(v, {1}, [&](uint64_t cell) {
        const int r = int(cell / f.cols), c = int(cell % f.cols);
        return r >= 3 && r <= 14 && c >= 5 && c <= 20;
    });
    EXPECT_EQ(t.at(0, 0).volume, double(ref.voxels) * voxel_volume(f));
    EXPECT_EQ(t.at(0, 0).cells, ref.cells);
}

TEST(Volumes, PolygonsWithHolesPerZone)
{
    const Voxels v = utm_voxels(3);
    const Model m = sbrt_test::build_model(v);
    const Frame &f = m.frame();
    const double x0 = f.west, y0 = f.south;
    // zone 0: a square with a square hole; zone 1: a triangle with slanted
    // edges; zone 2 is drawn nowhere (the model's cells lie outside it)
    const Polygon square = {
        {{x0 + 10, y0 + 10}, {x0 + 400, y0 + 10}, {x0 + 400, y0 + 300}, {x0 + 10, y0 + 300}},
        {{x0 + 100, y0 + 100}, {x0 + 200, y0 + 100}, {x0 + 200, y0 + 200}, {x0 + 100, y0 + 200}}};
    const Polygon triangle = {{{x0 + 450, y0 + 20}, {x0 + 770, y0 + 90}, {x0 + 500, y0 + 560},
                               {x0 + 450, y0 + 20}}};
    const Polygon outside = {{{x0 - 500, y0}, {x0 - 100, y0}, {x0 - 100, y0 + 300}}};
    CellZones zones = CellZones::none(f, 3);
    zones.add_polygon(square, 0);
    zones.add_polygon(triangle, 1);
    zones.add_polygon(outside, 2);
    const std::set<int32_t> ids{-6, 15};
    const VolumeTable t = measure_volumes(m, {ClassSet::named(m, {"-6", "15"})}, zones, 2);
    const Polygon *polygons[] = {&square, &triangle, &outside};
    uint64_t inside_cells = 0;
    for (int z = 0; z < 3; ++z) {
        const Reference ref = count_voxels(v, ids, [&](uint64_t cell) {
            const double x = f.west + (double(cell % f.cols) + 0.5) * f.ew_res();
            const double y = f.north - (double(cell / f.cols) + 0.5) * f.ns_res();
            const bool in = inside(*polygons[z], x, y);
            inside_cells += in;
            return in;
        });
        EXPECT_EQ(t.at(z, 0).volume, double(ref.voxels) * voxel_volume(f)) << "zone " << z;
        EXPECT_EQ(t.at(z, 0).cells, ref.cells) << "zone " << z;
    }
    EXPECT_GT(inside_cells, 100u); // the polygons do hold cells
    EXPECT_EQ(t.at(2, 0).cells, 0u);
}

TEST(Volumes, HorizonModelSumsContinuousThickness)
{
    Frame f;
    f.rows = 1;
    f.cols = 2;
    f.depths = 100;
    f.north = 20;
    f.south = 10;
    f.east = 10;
    f.west = 0; // cells of 5 x 10
    f.bottom = 0;
    f.top = 50; // tb_res 0.5
    std::vector<Material> units(2);
    units[0].id = 1;
    units[1].id = 2;
    HorizonStackBuilder b(f, units);
    const double u1[] = {30.25, 40.0};
    const double u2[] = {10.125, NAN};
    const double base[] = {2.5, 1.0};
    b.add_row({u1, u2}, base);
    const Model m = b.finish();
    const VolumeTable t = measure_volumes(m, every_class(m), CellZones::whole(f));
    EXPECT_EQ(t.at(0, 0).volume, 50.0 * ((30.25 - 10.125) + (40.0 - 1.0)));
    EXPECT_EQ(t.at(0, 0).cells, 2u);
    EXPECT_EQ(t.at(0, 1).volume, 50.0 * (10.125 - 2.5));
    EXPECT_EQ(t.at(0, 1).cells, 1u);
}

TEST(Volumes, ZonesOfAnotherModelAreRefused)
{
    const Voxels v = utm_voxels(2);
    const Model m = sbrt_test::build_model(v);
    Frame other = m.frame();
    other.cols += 1;
    EXPECT_THROW(measure_volumes(m, every_class(m), CellZones::whole(other)), Error);
    CellZones zones = CellZones::none(m.frame(), 1);
    EXPECT_THROW(zones.add_polygon({}, 1), Error);
}
