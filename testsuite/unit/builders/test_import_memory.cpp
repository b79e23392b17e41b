/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The least memory a file import needs, and the grid limits,
 *            checked before reading (issue 28, item 5)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <string>

#include <gtest/gtest.h>

#include "builders/import_memory.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

ImportGrid grid(uint64_t cols, uint64_t rows, uint64_t depths, uint64_t sample = 2)
{
    ImportGrid g;
    g.cols = cols;
    g.rows = rows;
    g.depths = depths;
    g.sample_bytes = sample;
    return g;
}

std::string error_of(const ImportGrid &g, double available)
{
    try {
        check_import_fits(g, 16 << 20, available, "variable 'v' of <f.nc>");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ImportMemory, GrowsWithCellsNotVoxels)
{
    const double small = import_bytes_at_least(grid(100, 100, 10), 16 << 20);
    EXPECT_NEAR(small, 100 * 100 * 5 + 8 * 210 + 2 * double(16 << 20), 1);
    // one northing row of whole columns is read at least
    EXPECT_DOUBLE_EQ(import_band_bytes(grid(30000, 1, 313), 1 << 20), 2.0 * 30000 * 313 * 2);
    EXPECT_DOUBLE_EQ(import_band_bytes(grid(10, 1, 10), 1 << 20), 2.0 * (1 << 20));
}

TEST(ImportMemory, Issue28DeclaredGridBeyondMemoryFailsWithTheFigures)
{
    // 30000 x 30000 x 313 declared: 9e8 cells, at least 4.5 GB
    const std::string m = error_of(grid(30000, 30000, 313), 4e9);
    EXPECT_NE(m.find("needs at least 4.5 GB"), std::string::npos) << m;
    EXPECT_NE(m.find("has 4.0 GB available"), std::string::npos) << m;
    EXPECT_NE(m.find("900000000 cells"), std::string::npos) << m;
    EXPECT_NE(m.find("variable 'v' of <f.nc>"), std::string::npos) << m;
    EXPECT_EQ(error_of(grid(30000, 30000, 313), 9e9), "");
    // unknown memory: no memory check
    EXPECT_EQ(error_of(grid(30000, 30000, 313), 0), "");
}

TEST(ImportMemory, GridsNoSbrtHoldsFailWhateverTheMemory)
{
    EXPECT_NE(error_of(grid(50000, 50000, 10), 0).find("at most 2^31-1"), std::string::npos);
    EXPECT_NE(error_of(grid(1ull << 40, 1ull << 40, 10), 1e30).find("at most 2^31-1"),
              std::string::npos);
    EXPECT_NE(error_of(grid(10, 10, (1 << 24) + 1), 0).find("at most 2^24"),
              std::string::npos);
    EXPECT_EQ(error_of(grid(46340, 46340, 1 << 24), 0), "");
}
