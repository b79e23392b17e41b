/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Band decoding of file imports: any index order and direction,
 *            every sample type, missing values, rules, and where a bad
 *            value is (issue 28: moved from r3.sbrt.convert)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "builders/band_classes.hpp"
#include "builders/band_import.hpp"
#include "builders/voxel_expander.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

constexpr int NX = 4, NY = 5, NZ = 6;
constexpr int FILL = -127;

/// classes[(row * NX + col) * NZ + depth]: row 0 north, depth 0 bottom;
/// runs of 1..3 with FILL (caves, air).
std::vector<int> reference(unsigned seed)
{
    std::mt19937 rng(seed);
    std::vector<int> v(size_t(NX) * NY * NZ);
    for (int &c : v)
        c = rng() % 4 == 0 ? FILL : int(1 + rng() % 3);
    return v;
}

/// \brief How a file lays the voxels out: dims in C order (axis 0 easting,
/// 1 northing, 2 vertical), each ascending or not.
struct Layout {
    std::array<int, 3> order;
    std::array<bool, 3> ascending;
};

BandGrid grid_of(const Layout &l, SampleType sample)
{
    BandGrid g;
    RegularAxis *axes[3] = {&g.easting, &g.northing, &g.vertical};
    const size_t sizes[3] = {NX, NY, NZ};
    for (int a = 0; a < 3; ++a) {
        axes[a]->size = sizes[a];
        axes[a]->ascending = l.ascending[a];
        axes[a]->resolution = 1;
        axes[a]->high_edge = double(sizes[a]);
    }
    g.missing.exact.push_back(FILL);
    g.sample = sample;
    return g;
}

/// The band of northing indices [first, first + count) as the file holds
/// it, in type T, with its strides.
template <typename T>
std::vector<T> band_of(const std::vector<int> &ref, const Layout &l, size_t first,
                       size_t count, BandStrides &step)
{
    const size_t counts[3] = {NX, count, NZ};
    size_t strides[3];
    size_t stride = 1;
    for (int d = 2; d >= 0; --d) {
        strides[l.order[d]] = stride;
        stride *= counts[l.order[d]];
    }
    step = {strides[0], strides[1], strides[2]};
    std::vector<T> out(stride);
    for (size_t j = 0; j < count; ++j)
        for (size_t i = 0; i < NX; ++i)
            for (size_t k = 0; k < NZ; ++k) {
                const size_t yi = first + j;
                const size_t row = l.ascending[1] ? NY - 1 - yi : yi;
                const size_t col = l.ascending[0] ? i : NX - 1 - i;
                const size_t depth = l.ascending[2] ? k : NZ - 1 - k;
                out[i * strides[0] + j * strides[1] + k * strides[2]] =
                    T(ref[(row * NX + col) * NZ + depth]);
            }
    return out;
}

Frame frame()
{
    Frame f;
    f.rows = NY;
    f.cols = NX;
    f.depths = NZ;
    f.north = NY;
    f.east = NX;
    f.top = NZ;
    return f;
}

/// Imports `ref` laid out as `l` in bands of `band` rows, as
/// r3.sbrt.convert reads them (north first; a file whose northing
/// ascends is read from its high indices down).
template <typename T>
Model import(const std::vector<int> &ref, const Layout &l, SampleType sample,
             Classifier &classifier, size_t band, uint64_t *unmatched = nullptr)
{
    const BandGrid grid = grid_of(l, sample);
    ColumnStackBuilder builder(frame());
    BandImport import(grid, classifier, builder);
    for (size_t row0 = 0; row0 < NY; row0 += band) {
        const size_t count = std::min(band, NY - row0);
        const size_t first = l.ascending[1] ? NY - row0 - count : row0;
        BandStrides step;
        const std::vector<T> values = band_of<T>(ref, l, first, count, step);
        import.add(values.data(), step, row0, count, first);
    }
    if (unmatched)
        *unmatched = import.unmatched();
    return builder.finish();
}

/// The model's voxels in `reference`'s order.
std::vector<int> voxels_of(const Model &model)
{
    VoxelExpander expander(model, model.frame());
    std::vector<int32_t> slice(size_t(NX) * NY);
    std::vector<int> out(size_t(NX) * NY * NZ);
    for (int z = 0; z < NZ; ++z) {
        expander.next_slice(slice.data());
        for (size_t cell = 0; cell < slice.size(); ++cell)
            out[cell * NZ + z] = slice[cell] == NULL_CLASS ? FILL : slice[cell];
    }
    return out;
}

} // namespace

TEST(BandImport, AnyIndexOrderAndDirectionGivesTheReference)
{
    const std::vector<int> ref = reference(5);
    std::array<int, 3> order = {0, 1, 2};
    do {
        for (int dirs = 0; dirs < 8; ++dirs) {
            const Layout l{order, {bool(dirs & 1), bool(dirs & 2), bool(dirs & 4)}};
            for (size_t band : {size_t(1), size_t(2), size_t(NY)}) {
                Classifier classifier;
                const Model m = import<int16_t>(ref, l, SampleType::int16, classifier, band);
                EXPECT_EQ(voxels_of(m), ref) << "order " << order[0] << order[1]
                                             << order[2] << " directions " << dirs
                                             << " band " << band;
            }
        }
    } while (std::next_permutation(order.begin(), order.end()));
}

TEST(BandImport, EverySampleTypeDecodes)
{
    std::vector<int> ref = reference(9);
    const Layout l{{1, 0, 2}, {true, true, true}};
    auto same = [&](auto zero, SampleType type) {
        using T = decltype(zero);
        Classifier classifier;
        EXPECT_EQ(voxels_of(import<T>(ref, l, type, classifier, 2)), ref)
            << int(type);
    };
    same(int8_t(), SampleType::int8);
    same(int16_t(), SampleType::int16);
    same(int32_t(), SampleType::int32);
    same(float(), SampleType::float32);
    same(double(), SampleType::float64);
    // unsigned types: fill 255 / 65535 / 2^32 - 1 as the missing value
    for (int &c : ref)
        c = c == FILL ? -1 : c;
    auto unsigned_same = [&](auto zero, SampleType type) {
        using T = decltype(zero);
        std::vector<int> as = ref;
        Classifier classifier;
        ColumnStackBuilder builder(frame());
        BandGrid grid = grid_of(l, type);
        grid.missing.exact = {double(T(-1))};
        BandImport import(grid, classifier, builder);
        for (size_t row0 = 0; row0 < NY; ++row0) {
            BandStrides step;
            const std::vector<T> values = band_of<T>(ref, l, NY - row0 - 1, 1, step);
            import.add(values.data(), step, row0, 1, NY - row0 - 1);
        }
        std::vector<int> back = voxels_of(builder.finish());
        for (int &c : as)
            c = c == -1 ? FILL : c;
        EXPECT_EQ(back, as) << int(type);
    };
    unsigned_same(uint8_t(), SampleType::uint8);
    unsigned_same(uint16_t(), SampleType::uint16);
    unsigned_same(uint32_t(), SampleType::uint32);
    EXPECT_EQ(sample_bytes(SampleType::uint16), 2u);
    EXPECT_EQ(sample_bytes(SampleType::float64), 8u);
}

TEST(BandImport, RulesClassifyAndCountUncoveredVoxels)
{
    const std::vector<int> ref = reference(11);
    const Layout l{{0, 1, 2}, {true, false, true}};
    Classifier classifier({{1, 2, 7, "low"}});
    uint64_t unmatched = 0;
    const std::vector<int> back =
        voxels_of(import<float>(ref, l, SampleType::float32, classifier, 3, &unmatched));
    uint64_t threes = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
        threes += ref[i] == 3;
        EXPECT_EQ(back[i], ref[i] == 1 || ref[i] == 2 ? 7 : FILL) << i;
    }
    EXPECT_EQ(unmatched, threes);
}

TEST(BandImport, ABadValueIsNamedByRowColumnAndDepth)
{
    std::vector<int> ref = reference(13);
    const Layout l{{2, 1, 0}, {false, true, true}};
    // float values: 2.5 at row 3, column 2, depth 4 (1-based: 4, 3, 5)
    std::vector<double> values;
    const BandGrid grid = grid_of(l, SampleType::float64);
    ColumnStackBuilder builder(frame());
    Classifier classifier;
    BandImport import(grid, classifier, builder);
    BandStrides step;
    values = band_of<double>(ref, l, 0, NY, step);
    // northing ascends: row 3 is index NY - 1 - 3; easting descends
    values[(NX - 1 - 2) * step.easting + (NY - 1 - 3) * step.northing + 4 * step.vertical] = 2.5;
    try {
        import.add(values.data(), step, 0, NY, 0);
        FAIL() << "no error";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("row 4, column 3, depth 5"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("2.5"), std::string::npos) << e.what();
    }
}

TEST(BandClasses, SmallIntegersUseTheTableWithMissingValues)
{
    MissingValues missing;
    missing.exact = {-127};
    missing.valid_max = 100;
    Classifier plain;
    BandClasses<int8_t> classes(missing, plain);
    EXPECT_EQ(classes(int8_t(5)), 5);
    EXPECT_EQ(classes(int8_t(-127)), NULL_CLASS);
    EXPECT_EQ(classes(int8_t(101)), NULL_CLASS);
    EXPECT_EQ(classes(int8_t(-128)), -128);
    BandClasses<uint16_t> wide(missing, plain);
    EXPECT_EQ(wide(uint16_t(65535)), NULL_CLASS);
    EXPECT_EQ(wide(uint16_t(100)), 100);
    // with rules every value goes through them
    Classifier rules({{0, 10, 1, "a"}});
    BandClasses<int16_t> ruled(missing, rules);
    EXPECT_EQ(ruled(int16_t(4)), 1);
    EXPECT_EQ(ruled(int16_t(40)), NULL_CLASS);
    EXPECT_EQ(ruled(int16_t(-127)), NULL_CLASS);
}
