/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   Untrusted text made safe (issue 48, items 1, 2, 4 and 9):
 *            UTF-8 repaired, control characters kept from terminals, one
 *            shell word that a shell reads back and never runs, a byte
 *            budget cut on a character boundary
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>

#include "util/safe_text.hpp"

using namespace sbrt;

namespace {

const std::string FFFD = "\xEF\xBF\xBD";

/// What `sh -c 'eval "x=WORD"; printf %s "$x"'` makes of a word, and
/// whether the shell ran anything beside the assignment (a marker file).
std::string shell_reads(const std::string &word)
{
    const std::string script = "x=" + word + "; printf %s \"$x\"";
    FILE *file = std::fopen("/tmp/sbrt_shell_word.sh", "w");
    std::fputs(script.c_str(), file);
    std::fclose(file);
    FILE *pipe = popen("cd /tmp && eval \"$(cat /tmp/sbrt_shell_word.sh)\"", "r");
    std::string out;
    std::array<char, 256> buffer;
    size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        out.append(buffer.data(), n);
    pclose(pipe);
    return out;
}

} // namespace

TEST(SafeText, ValidUtf8KeepsGoodTextAndReplacesBadBytes)
{
    EXPECT_TRUE(is_valid_utf8("zand, grof (Dünen) \xE2\x82\xAC"));
    EXPECT_EQ(valid_utf8("zand \xC3\xBC"), "zand \xC3\xBC");
    EXPECT_FALSE(is_valid_utf8("bad \xFF label"));
    EXPECT_EQ(valid_utf8("bad \xFF label"), "bad " + FFFD + " label");
    // overlong '/', a surrogate, past U+10FFFF, a cut sequence
    EXPECT_EQ(valid_utf8("\xC0\xAF"), FFFD + FFFD);
    EXPECT_EQ(valid_utf8("\xED\xA0\x80"), FFFD + FFFD + FFFD);
    EXPECT_EQ(valid_utf8("\xF4\x90\x80\x80"), FFFD + FFFD + FFFD + FFFD);
    EXPECT_EQ(valid_utf8("end \xE2\x82"), "end " + FFFD + FFFD);
    EXPECT_TRUE(is_valid_utf8(valid_utf8("\xFE\xFF\x80\xC3")));
}

TEST(SafeText, PrintableHasNoControlCharacters)
{
    EXPECT_EQ(printable("ctrl\x01\x1b[31mred"), "ctrl" + FFFD + FFFD + "[31mred");
    EXPECT_EQ(printable("a\tb\nc\x7f"), "a" + FFFD + "b" + FFFD + "c" + FFFD);
    EXPECT_EQ(printable("c1 \xC2\x9B" "31m"), "c1 " + FFFD + "31m"); // C1 CSI
    EXPECT_EQ(printable("klei \xC3\xA9\xC2\xA0"), "klei \xC3\xA9\xC2\xA0"); // NBSP stays
    EXPECT_EQ(printable_lines("one\x1b[2J\ntwo\r"), "one" + FFFD + "[2J\ntwo" + FFFD);
}

TEST(SafeText, ShellWordIsReadBackAndRunsNothing)
{
    std::remove("/tmp/PWNED_safe_text");
    for (const std::string value :
         {"x; touch PWNED_safe_text; echo", "%$(touch PWNED_safe_text)",
          "`touch PWNED_safe_text`", "it's \"quoted\" $HOME", "Elevation (m NAP)",
          "a|b&c>d<e*?[x]~{y}", "kans op lithoklasse 5", "' ; touch PWNED_safe_text '"}) {
        const std::string word = shell_word(value);
        EXPECT_EQ(shell_reads(word), value) << word;
    }
    EXPECT_NE(std::fopen("/tmp/PWNED_safe_text", "r") ? 1 : 0, 1);
    EXPECT_EQ(shell_word("kans_5"), "kans_5");
    EXPECT_EQ(shell_word("%"), "%");
    EXPECT_EQ(shell_word("-12.5,3e+07"), "-12.5,3e+07");
    EXPECT_EQ(shell_word(""), "");
    EXPECT_EQ(shell_word("line\nbreak"), "'line" + FFFD + "break'");
}

TEST(SafeText, CsvFieldIsQuotedWhereItMustBe)
{
    EXPECT_EQ(csv_field("clay"), "clay");
    EXPECT_EQ(csv_field("clay, stiff"), "\"clay, stiff\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv_field("a;b", ';'), "\"a;b\"");
    EXPECT_EQ(csv_field("a,b", ';'), "a,b");
    EXPECT_EQ(csv_field("line\nbreak\x1b"), "line" + FFFD + "break" + FFFD);
}

TEST(SafeText, JsonControlsEscaped)
{
    EXPECT_EQ(escape_json_controls("{\"a\": \"x\x7fy\xC2\x9B" "31m\xC3\xBC\"}"),
              "{\"a\": \"x\\u007fy\\u009b31m\xC3\xBC\"}");
}

TEST(SafeText, FitBytesCutsOnACharacterBoundary)
{
    EXPECT_EQ(fit_bytes("short", 10), "short");
    EXPECT_EQ(fit_bytes("abcdefghijkl", 10), "abcdefg...");
    // a 2-byte character across the cut is left out whole
    const std::string cut = fit_bytes("abcdef\xC3\xBC" "xyz", 10);
    EXPECT_EQ(cut, "abcdef...");
    EXPECT_TRUE(is_valid_utf8(cut));
    EXPECT_LE(fit_bytes(std::string(5000, 'x'), 1023).size(), 1023u);
    EXPECT_EQ(fit_bytes("abcdef", 4), "abcd");
}
