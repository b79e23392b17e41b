/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Colour rules files read as untrusted input (issue 48, items 5
 *            and 6): GRASS's syntax is read, every bad line is refused
 *            with its number and never quoted, and only regular files of
 *            bounded size are read
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "model/color_rules.hpp"
#include "util/error.hpp"

using namespace sbrt;

namespace {

/// The message of the error parse_color_rules throws for `text`.
std::string error_of(const std::string &text)
{
    try {
        parse_color_rules(text, "rules=test");
    }
    catch (const Error &e) {
        return e.what();
    }
    return "(no error)";
}

/// A folder of its own for the files of one test.
struct Folder {
    std::filesystem::path path;
    Folder()
    {
        char name[] = "/tmp/sbrt_color_rules_XXXXXX";
        path = mkdtemp(name);
    }
    ~Folder() { std::filesystem::remove_all(path); }
    std::string write(const std::string &name, const std::string &text) const
    {
        const std::string file = (path / name).string();
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
};

} // namespace

TEST(ColorRules, ReadsGrassSyntax)
{
    const ColorRules r = parse_color_rules(
        "# a comment\n\n  0% blue\n50%\t#00FF80\n100% 255 0 0\r\n7 10:20:30\n"
        "-2.5e1 1,2;3\n+3 Grey\nnv white\nDEFAULT black\n",
        "rules=test");
    ASSERT_EQ(r.rules.size(), 6u);
    EXPECT_TRUE(r.rules[0].percent);
    EXPECT_EQ(r.rules[0].rgb, (Rgb{0, 0, 255}));
    EXPECT_EQ(r.rules[1].rgb, (Rgb{0, 255, 128}));
    EXPECT_DOUBLE_EQ(r.rules[1].value_in(10, 20), 15);
    EXPECT_EQ(r.rules[2].rgb, (Rgb{255, 0, 0}));
    EXPECT_FALSE(r.rules[3].percent);
    EXPECT_DOUBLE_EQ(r.rules[3].value, 7);
    EXPECT_EQ(r.rules[3].rgb, (Rgb{10, 20, 30}));
    EXPECT_DOUBLE_EQ(r.rules[4].value, -25);
    EXPECT_EQ(r.rules[4].rgb, (Rgb{1, 2, 3}));
    EXPECT_EQ(r.rules[5].rgb, (Rgb{128, 128, 128}));
    ASSERT_TRUE(r.null_color && r.default_color);
    EXPECT_EQ(*r.null_color, (Rgb{255, 255, 255}));
    EXPECT_EQ(*r.default_color, (Rgb{0, 0, 0}));
}

TEST(ColorRules, BadLinesNamedByNumberNeverQuoted)
{
    const struct {
        const char *text;
        int line;
        const char *hidden;
    } cases[] = {
        {"5 300:0:0\n", 1, "300:0:0"},
        {"1 red\n\n# x\n50 nonsense_colour\n", 4, "nonsense_colour"},
        {"root:x:0:0:root:/root:/bin/bash\n", 1, "root:x"},
        {"0 red\nnan red\n", 2, "nan"},
        {"0 red\n1e999 red\n", 2, "1e999"},
        {"0 red\ninf red\n", 2, "inf red"},
        {"101% red\n", 1, "101%"},
        {"-1% red\n", 1, "-1%"},
        {"5 1:2\n", 1, "1:2"},
        {"5 1:2:3:4\n", 1, "1:2:3:4"},
        {"5 -1:2:3\n", 1, "-1:2:3"},
        {"5 #12345\n", 1, "#12345"},
        {"5 #12345g\n", 1, "#12345g"},
        {"5 none\n", 1, "none"},
        {"5\n", 1, "5\n"},
        {"5abc red\n", 1, "5abc"},
        {"0x10 red\n", 1, "0x10"},
    };
    for (const auto &c : cases) {
        const std::string message = error_of(c.text);
        EXPECT_NE(message.find("rules=test: line " + std::to_string(c.line) + ":"),
                  std::string::npos)
            << c.text << ": " << message;
        EXPECT_EQ(message.find(c.hidden), std::string::npos) << message;
    }
    // a NUL in a line (a binary file)
    EXPECT_NE(error_of(std::string("0 red\n5 bl\0ue\n", 14)).find("line 2:"),
              std::string::npos);
    // a file of nothing but comments and an nv line has no rule
    EXPECT_NE(error_of("# only\nnv red\n").find("no colour rules"), std::string::npos);
    // a line far beyond GRASS's 80-byte value buffer is an error, no more
    EXPECT_NE(error_of(std::string(100000, '7') + " red\n").find("line 1:"),
              std::string::npos);
}

TEST(ColorRules, NamedColors)
{
    EXPECT_EQ(named_color("BROWN"), (Rgb{180, 77, 25}));
    EXPECT_EQ(named_color("aqua"), (Rgb{100, 128, 255}));
    EXPECT_FALSE(named_color("nonsense_colour"));
    EXPECT_FALSE(named_color(""));
}

TEST(ColorRules, OnlyRegularFilesOfBoundedSize)
{
    Folder folder;
    const std::string good = folder.write("good.rules", "0% blue\n100% red\n");
    EXPECT_EQ(read_color_rules_file(good, "rules=" + good).rules.size(), 2u);

    // a FIFO is refused, not waited on (a test that hangs here fails)
    const std::string fifo = (folder.path / "fifo").string();
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    // a link to a rules file is followed, as for any file named on a
    // command line; a link to a FIFO is refused as the FIFO is
    const std::string link = (folder.path / "link").string();
    ASSERT_EQ(symlink(good.c_str(), link.c_str()), 0);
    EXPECT_EQ(read_color_rules_file(link, "rules=" + link).rules.size(), 2u);
    const std::string fifo_link = (folder.path / "fifo_link").string();
    ASSERT_EQ(symlink(fifo.c_str(), fifo_link.c_str()), 0);
    // a device, a directory, a file too large, a missing one
    const std::string large =
        folder.write("large.rules", std::string(MAX_COLOR_RULES_BYTES + 1, '#'));
    const struct {
        std::string path, words;
    } refused[] = {
        {fifo, "FIFO"},
        {"/dev/zero", "character device"},
        {fifo_link, "FIFO"},
        {folder.path.string(), "directory"},
        {large, "more than"},
        {(folder.path / "missing").string(), "cannot open"},
    };
    for (const auto &r : refused) {
        try {
            read_color_rules_file(r.path, "rules=" + r.path);
            ADD_FAILURE() << r.path << " was read";
        }
        catch (const Error &e) {
            EXPECT_NE(std::string(e.what()).find(r.words), std::string::npos) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind("rules=" + r.path, 0), 0u) << e.what();
        }
    }
}

TEST(ColorRules, StreamIsBounded)
{
    // /dev/zero as standard input: refused after the bound, not read forever
    std::FILE *zero = std::fopen("/dev/zero", "rb");
    ASSERT_NE(zero, nullptr);
    EXPECT_THROW(read_color_rules_stream(zero, "rules=-"), Error);
    std::fclose(zero);
}
