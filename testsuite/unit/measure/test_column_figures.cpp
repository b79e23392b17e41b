/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Top, base, thickness, layers and depth of class sets from the
 *            intervals against the same figures counted voxel by voxel
 *            (holes, caves, overhangs, filled columns, UTM coordinates,
 *            wide records) and against horizons with continuous tops
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "builders/horizon_builder.hpp"
#include "measure/centre_sampling.hpp"
#include "measure/class_set.hpp"
#include "measure/column_figures.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;
using sbrt_test::Voxels;

namespace {

/// The figures of the class ids `set` in cell `cell`, voxel by voxel.
MapFigures voxel_reference(const Voxels &v, uint64_t cell, const std::set<int32_t> &set,
                           bool &present)
{
    const Frame &f = v.frame;
    MapFigures m;
    int lowest = -1, highest = -1, surface = -1, count = 0;
    bool before = false;
    for (int z = 0; z < f.depths; ++z) {
        const int32_t id = v.classes[size_t(z) * f.cells() + cell];
        const bool in = set.count(id) > 0;
        if (id != NULL_CLASS)
            surface = z;
        if (in) {
            if (lowest < 0)
                lowest = z;
            highest = z;
            ++count;
            if (!before)
                ++m.layers;
        }
        before = in;
    }
    present = count > 0;
    m.top = f.bottom + (highest + 1) * f.tb_res();
    m.base = f.bottom + lowest * f.tb_res();
    m.thickness = count * f.tb_res();
    m.depth = (surface - highest) * f.tb_res();
    return m;
}

std::vector<std::string> names_of(const std::set<int32_t> &ids)
{
    std::vector<std::string> names;
    for (int32_t id : ids)
        names.push_back(std::to_string(id));
    return names;
}

/// Every cell of `v`'s model against the voxel reference, for `set`.
void expect_voxel_figures(const Voxels &v, const Model &m, const std::set<int32_t> &set,
                          const std::string &what)
{
    const ClassSet classes = ClassSet::named(m, names_of(set));
    int present_cells = 0;
    for (uint64_t cell = 0; cell < v.frame.cells(); ++cell) {
        bool present = false;
        const MapFigures want = voxel_reference(v, cell, set, present);
        const ColumnFigures got = column_figures(m, cell, classes);
        ASSERT_EQ(got.present(), present) << what << " cell " << cell;
        if (!present)
            continue;
        ++present_cells;
        const MapFigures map = map_figures(m.frame(), got);
        EXPECT_EQ(map.top, want.top) << what << " cell " << cell;
        EXPECT_EQ(map.base, want.base) << what << " cell " << cell;
        EXPECT_EQ(map.thickness, want.thickness) << what << " cell " << cell;
        EXPECT_EQ(map.depth, want.depth) << what << " cell " << cell;
        EXPECT_EQ(map.layers, want.layers) << what << " cell " << cell;
    }
    EXPECT_GT(present_cells, 0) << what << ": the set should be somewhere";
}

Voxels hand_column(std::vector<int32_t> bottom_up)
{
    Voxels v;
    v.frame.rows = 1;
    v.frame.cols = 1;
    v.frame.depths = int(bottom_up.size());
    v.frame.bottom = 100;
    v.frame.top = 100 + 2.0 * v.frame.depths; // tb_res 2
    v.classes = bottom_up;
    return v;
}

constexpr int32_t N = NULL_CLASS;

} // namespace

TEST(ColumnFigures, HandMadeColumnWithCaveAndOverhang)
{
    // bottom up: 1 1 (cave) 2 1 1 (cave) 3 1 ; tb_res 2, bottom 100
    const Voxels v = hand_column({1, 1, N, 2, 1, 1, N, 3, 1});
    const Model m = sbrt_test::build_model(v);
    const ColumnFigures f = column_figures(m, 0, ClassSet::named(m, {"1"}));
    const MapFigures map = map_figures(m.frame(), f);
    EXPECT_EQ(map.layers, 3u);        // 0-2, 4-6, 8-9: caves and class 2/3 part them
    EXPECT_EQ(map.thickness, 10.0);   // 5 voxels of 2
    EXPECT_EQ(map.base, 100.0);
    EXPECT_EQ(map.top, 118.0);
    EXPECT_EQ(map.depth, 0.0);        // class 1 is the surface
    const MapFigures two_three =
        map_figures(m.frame(), column_figures(m, 0, ClassSet::named(m, {"2", "3"})));
    EXPECT_EQ(two_three.layers, 2u);
    EXPECT_EQ(two_three.top, 116.0);
    EXPECT_EQ(two_three.base, 106.0);
    EXPECT_EQ(two_three.thickness, 4.0);
    EXPECT_EQ(two_three.depth, 2.0);
    // adjacent set intervals merge into one layer: 2 then 1 1 is one run
    const MapFigures one_two =
        map_figures(m.frame(), column_figures(m, 0, ClassSet::named(m, {"1", "2"})));
    EXPECT_EQ(one_two.layers, 3u); // 0-2 | 3-6 | 8-9
    EXPECT_EQ(one_two.thickness, 12.0);
}

TEST(ColumnFigures, AbsentSetAndEmptyColumn)
{
    const Voxels v = hand_column({1, 2, N, N});
    const Model m = sbrt_test::build_model(v);
    EXPECT_FALSE(column_figures(m, 0, ClassSet::of_materials(m, {})).present());
    Voxels empty = hand_column({N, N, N});
    empty.classes = {N, N, N};
    Voxels two = hand_column({1, N, N, 1, N, N});
    two.frame.cols = 2;
    two.frame.depths = 3;
    two.classes = {N, 1, N, N, N, 1}; // cell 0 empty; cell 1: 1 (cave) 1
    const Model mt = sbrt_test::build_model(two);
    const ClassSet one = ClassSet::named(mt, {"1"});
    EXPECT_FALSE(column_figures(mt, 0, one).present());
    const ColumnFigures f = column_figures(mt, 1, one);
    EXPECT_EQ(f.layers, 2u);
    EXPECT_EQ(f.thickness, 2.0);
    EXPECT_EQ(f.top, 3.0);
    EXPECT_EQ(f.base, 0.0);
}

TEST(ColumnFigures, RandomVoxelModelsEqualTheVoxelCount)
{
    for (unsigned seed = 1; seed <= 12; ++seed) {
        const Voxels v = sbrt_test::random_voxels(seed, 4 + seed % 5, 3 + seed % 4,
                                                  5 + int(seed * 7 % 41), 6);
        const Model m = sbrt_test::build_model(v);
        const std::string what = "seed " + std::to_string(seed);
        // ids of random_voxels: k * 7 - 20 for k = 1..6
        expect_voxel_figures(v, m, {-13}, what + " one class");
        expect_voxel_figures(v, m, {-13, 1, 15}, what + " three classes");
        expect_voxel_figures(v, m, {-13, -6, 1, 8, 15, 22}, what + " every class");
        // the same model with its records held wide (horizon models, v1 files)
        expect_voxel_figures(v, sbrt_test::widened(m), {-6, 8}, what + " wide");
    }
}

TEST(ColumnFigures, UtmCoordinatesAndFilledColumns)
{
    Voxels v = sbrt_test::random_voxels(77, 6, 7, 60, 4);
    v.frame.north = 5800000 + 6 * 25.0;
    v.frame.south = 5800000;
    v.frame.west = 450000;
    v.frame.east = 450000 + 7 * 25.0;
    v.frame.bottom = -187.5;
    v.frame.top = -187.5 + 60 * 0.5;
    // fill the upper half of some columns to the top (no air above)
    for (uint64_t cell = 0; cell < v.frame.cells(); cell += 3)
        for (int z = 30; z < 60; ++z)
            v.classes[size_t(z) * v.frame.cells() + cell] = 1;
    const Model m = sbrt_test::build_model(v);
    expect_voxel_figures(v, m, {1}, "utm fill");
    expect_voxel_figures(v, m, {-13, 8}, "utm pair");
}

TEST(ColumnFigures, HorizonModelKeepsContinuousTops)
{
    // one row of 3 cells, units top to bottom 10, 20, 30; tb_res 0.25 from
    // -40, tops exact in float32 local units (multiples of 1/32 m)
    Frame f;
    f.rows = 1;
    f.cols = 3;
    f.depths = 400;
    f.bottom = -40;
    f.top = 60;
    std::vector<Material> units(3);
    units[0].id = 10;
    units[1].id = 20;
    units[2].id = 30;
    HorizonStackBuilder b(f, units);
    const double u10[] = {50.28125, 12.5, 30.0};
    const double u20[] = {20.03125, NAN, 31.5}; // absent in cell 1; below unit 30 in cell 2
    const double u30[] = {-3.96875, -10.0, 31.75};
    const double base[] = {-35.5, NAN, -20.0};
    b.add_row({u10, u20, u30}, base);
    const Model m = b.finish();
    const ClassSet s20 = ClassSet::named(m, {"20"});
    const ClassSet s1030 = ClassSet::named(m, {"10", "30"});

    const MapFigures c0 = map_figures(f, column_figures(m, 0, s20));
    EXPECT_EQ(c0.top, 20.03125);
    EXPECT_EQ(c0.base, -3.96875);
    EXPECT_EQ(c0.thickness, 20.03125 + 3.96875);
    EXPECT_EQ(c0.depth, 50.28125 - 20.03125);
    EXPECT_EQ(c0.layers, 1u);
    const MapFigures c0b = map_figures(f, column_figures(m, 0, s1030));
    EXPECT_EQ(c0b.layers, 2u);
    EXPECT_EQ(c0b.thickness, (50.28125 - 20.03125) + (-3.96875 + 35.5));
    EXPECT_EQ(c0b.base, -35.5);
    EXPECT_EQ(c0b.top, 50.28125);
    // cell 1: unit 20 absent, 10 sits on 30, one layer from the frame bottom
    EXPECT_FALSE(column_figures(m, 1, s20).present());
    const MapFigures c1 = map_figures(f, column_figures(m, 1, s1030));
    EXPECT_EQ(c1.layers, 1u);
    EXPECT_EQ(c1.base, -40.0);
    EXPECT_EQ(c1.top, 12.5);
    EXPECT_EQ(c1.thickness, 52.5);
    // cell 2: the uppermost horizon (unit 10 at 30.0) cuts the units below
    // it: 20 and 30 end there, 20 with no thickness (absent), 10 absent too
    EXPECT_FALSE(column_figures(m, 2, s20).present());
    EXPECT_FALSE(column_figures(m, 2, ClassSet::named(m, {"10"})).present());
    const MapFigures c2 = map_figures(f, column_figures(m, 2, ClassSet::named(m, {"30"})));
    EXPECT_EQ(c2.top, 30.0);
    EXPECT_EQ(c2.base, -20.0);
    EXPECT_EQ(c2.thickness, 50.0);
    EXPECT_EQ(c2.depth, 0.0);
}

TEST(ClassSet, IdsLabelsAndUnknownNames)
{
    sbrt_test::Voxels v = hand_column({5, 9, 5});
    sbrt::VoxelStackBuilder builder(v.frame);
    for (int z = 0; z < v.frame.depths; ++z)
        builder.add_slice(v.slice(z));
    std::vector<Material> legend(2);
    legend[0].id = 5;
    legend[0].label = "Fine sand";
    legend[1].id = 9;
    legend[1].label = "Clay";
    const Model m = builder.finish(legend);
    const ClassSet set = ClassSet::named(m, {"fine SAND", "9", "5"});
    ASSERT_EQ(set.materials().size(), 2u);
    EXPECT_EQ(set.describe(m), "5 (Fine sand), 9 (Clay)");
    try {
        ClassSet::named(m, {"Gravel"});
        FAIL() << "an unknown label must throw";
    }
    catch (const Error &e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'Gravel'"), std::string::npos) << message;
        EXPECT_NE(message.find("5 (Fine sand), 9 (Clay)"), std::string::npos) << message;
    }
    EXPECT_THROW(ClassSet::named(m, {"7"}), Error);
    EXPECT_THROW(ClassSet::named(m, {""}), Error);
}

TEST(CentreSampling, ModelGridFinerGridAndOutside)
{
    Frame f;
    f.rows = 3;
    f.cols = 4;
    f.north = 5800030;
    f.south = 5800000;
    f.west = 450000;
    f.east = 450040;
    const CentreSampling same = sample_at_centres(f, model_grid(f));
    EXPECT_EQ(same.model_row, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(same.model_col, (std::vector<int>{0, 1, 2, 3}));
    // twice as fine, shifted half a model cell west and north
    const GridWindow fine{5800035, 5800005, 450035, 449995, 6, 8};
    const CentreSampling s = sample_at_centres(f, fine);
    EXPECT_EQ(s.model_row, (std::vector<int>{-1, 0, 0, 1, 1, 2}));
    EXPECT_EQ(s.model_col, (std::vector<int>{-1, 0, 0, 1, 1, 2, 2, 3}));
    EXPECT_THROW(sample_at_centres(f, GridWindow{1, 1, 1, 0, 1, 1}), Error);
}
