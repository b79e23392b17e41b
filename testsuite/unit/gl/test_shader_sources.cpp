/****************************************************************************
 * MODULE:    testsuite/unit (r3.sbrt addon)
 * PURPOSE:   The shading programs' sources hold one copy of the shading:
 *            a driver that inlines every call (NVIDIA's) compiles each
 *            place that calls it; with a copy at each place a borehole's
 *            walk could end, an H100 took 100 s to compile the boreholes'
 *            program
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <gtest/gtest.h>

#include <cctype>
#include <sstream>
#include <string>

#include "shader_sources.hpp"

namespace {

/// `source` without its // comments.
std::string without_comments(const std::string &source)
{
    std::string code;
    for (size_t at = 0; at < source.size();) {
        const size_t comment = source.find("//", at);
        if (comment == std::string::npos) {
            code += source.substr(at);
            break;
        }
        code += source.substr(at, comment - at);
        const size_t line_end = source.find('\n', comment);
        at = line_end == std::string::npos ? source.size() : line_end;
    }
    return code;
}

/// The places in `sources` (comments left out) that call `function`: its
/// name and "(" not after a return type (the definition).
int calls_of(const std::string &function, std::initializer_list<const char *> sources)
{
    int calls = 0;
    for (const char *source : sources) {
        const std::string code = without_comments(source);
        for (size_t at = code.find(function + "("); at != std::string::npos;
             at = code.find(function + "(", at + 1)) {
            const bool part_of_a_name =
                at > 0 && (std::isalnum(static_cast<unsigned char>(code[at - 1])) ||
                           code[at - 1] == '_');
            // a definition: the line holds only a return type before it
            // (a word, not `return` or `else`)
            const size_t line_start = code.rfind('\n', at) + 1; // npos + 1: 0
            std::istringstream before(code.substr(line_start, at - line_start));
            std::string word, more;
            const bool definition = bool(before >> word) && !(before >> more) &&
                                    word != "return" && word != "else" &&
                                    std::isspace(static_cast<unsigned char>(code[at - 1]));
            if (!part_of_a_name && !definition)
                ++calls;
        }
    }
    return calls;
}

} // namespace

TEST(ShaderSources, TheRaycastProgramsShadeInOnePlace)
{
    using namespace sbrt_gl;
    const auto program = {SHADER_COMMON_LAYOUT, SHADER_COMMON_SHADE, SHADER_COMMON_RAY,
                          SHADER_COMMON_OVERLAYS, SHADER_COMMON_CLIP, SHADER_COMMON_WALK,
                          SHADER_COMMON_TRACE_PIXEL, SHADER_SHADE};
    // the shading: written once, after the trace, from what its end kept
    EXPECT_EQ(calls_of("write_pixel", program), 1);
    EXPECT_EQ(calls_of("write_kept_pixel", program), 1);
    EXPECT_EQ(calls_of("paint_color", program), 1);
    // what a borehole's walk inlines: one walk of a log's pieces, one of
    // the model's stack in a cell; one meeting a walk's direction, one a
    // curtain's
    EXPECT_EQ(calls_of("ov_walk", program), 2);
    EXPECT_EQ(calls_of("ov_borehole", program), 1);
    EXPECT_EQ(calls_of("ov_meet", program), 3);
    // the kernel's shading pass: one write of its own (shade.glsl's
    // write_kept_pixel never called there)
    const auto kernel = {SHADER_COMMON_KERNEL, SHADER_COMMON_KERNEL_NORMAL, SHADER_KERNEL_SHADE};
    EXPECT_EQ(calls_of("write_pixel", kernel), 1);
    EXPECT_EQ(calls_of("write_kept_pixel", kernel), 0);
}

TEST(ShaderSources, EachKernelPassHasItsOwnEntryFile)
{
    using namespace sbrt_gl;
    // one main() a program, the passes' shared code in the libraries
    for (const char *library : {SHADER_COMMON_KERNEL, SHADER_COMMON_KERNEL_NORMAL})
        EXPECT_EQ(std::string(library).find("void main()"), std::string::npos);
    for (const char *entry : {SHADER_KERNEL_DEPTH, SHADER_KERNEL_NORMALS, SHADER_KERNEL_ACROSS,
                              SHADER_KERNEL_SHADE})
        EXPECT_NE(std::string(entry).find("void main()"), std::string::npos);
    // a hit's kernel normal, written once, for the normals and shading
    EXPECT_EQ(calls_of("kernel_normal", {SHADER_COMMON_KERNEL_NORMAL}), 1);
    EXPECT_EQ(calls_of("hit_kernel_normal", {SHADER_KERNEL_NORMALS, SHADER_KERNEL_SHADE}), 2);
}

TEST(ShaderSources, CallsAreCountedWithoutDefinitionsAndComments)
{
    const char *source = "void f(uint a)\n{\n}\n"
                         "// f(1) in a comment\n"
                         "void g() { f(1u); if (ok) f(2u); g_f(3u); }\n"
                         "bool h = f(4u) == 0;\n"
                         "uint k() { return f(5u); }\n"
                         "    return f(6u);\n"
                         "    else f(7u);\n";
    EXPECT_EQ(calls_of("f", {source}), 6);
    EXPECT_EQ(calls_of("g", {source}), 0);
}
