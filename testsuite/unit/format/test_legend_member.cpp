/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The `colors` member and rewrite_legend: labels and colours
 *            changed after import, atomically, the stacks linked not
 *            rewritten (issue 31)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "format/format.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

ino_t inode_of(const std::string &path)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

std::string text_of(const std::string &path)
{
    std::ifstream in(path);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

} // namespace

TEST(LegendMember, ColoursRoundTripAndRewriteKeepsTheStacks)
{
    const std::string dir = sbrt_test::temp_dir("legend_member") + "/m";
    Model model = sbrt_test::build_model(sbrt_test::random_voxels(7, 6, 5, 4, 3));
    ASSERT_GE(model.materials().size(), 3u);
    model.materials()[1].has_color = true;
    model.materials()[1].red = 10;
    write_sbrt(dir, model, "created: test\n");
    Model back = read_sbrt(dir);
    EXPECT_TRUE(back.materials()[1].has_color);
    EXPECT_EQ(back.materials()[1].red, 10);
    EXPECT_FALSE(back.materials()[2].has_color);

    const ino_t stacks = inode_of(dir + "/stacks");
    back.materials()[1].has_color = false; // back to the palette
    back.materials()[2].has_color = true;
    back.materials()[2].green = 77;
    back.materials()[2].label = "sand";
    rewrite_legend(dir, back, "legend: test\n");
    const Model again = read_sbrt(dir);
    EXPECT_FALSE(again.materials()[1].has_color); // `colors` is the truth
    EXPECT_TRUE(again.materials()[2].has_color);
    EXPECT_EQ(again.materials()[2].green, 77);
    EXPECT_EQ(again.materials()[2].label, "sand");
    EXPECT_EQ(inode_of(dir + "/stacks"), stacks); // linked, not rewritten
    EXPECT_EQ(text_of(dir + "/hist"), "created: test\nlegend: test\n");
}

TEST(LegendMember, BadColoursLineIsNamed)
{
    Model model = sbrt_test::build_model(sbrt_test::random_voxels(3, 4, 4, 3, 3));
    try {
        decode_colors("1 1:2:3\n2 red\n", model, "m/colors");
        FAIL() << "no error";
    }
    catch (const Error &e) {
        EXPECT_NE(std::string(e.what()).find("m/colors line 2: expected id red:green:blue"),
                  std::string::npos)
            << e.what();
    }
}
