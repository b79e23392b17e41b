/****************************************************************************
 * MODULE:    testsuite/fuzz (r3.sbrt addon)
 * PURPOSE:   libFuzzer target of what the view server (r3.sbrt.render
 *            --serve) reads besides its request lines: colour rules files
 *            (rules=, property_color=) and an SBRT's legend texts (class
 *            labels, channel names, units and titles). Each input is cut
 *            into a request line, a legend and a rules file; the request
 *            line is read as the server reads it, the rules file is applied
 *            to the materials and read as a property's ramp as the server
 *            does, and the legend and any error are written as the
 *            server's reply lines. Fails on a crash, a leak, undefined
 *            behaviour, a hang, an exit (G_fatal_error in GRASS's rule
 *            reader would end the server), a reply that is not one
 *            printable line, a channel record of other than three fields,
 *            or an error that quotes a line of the rules file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "grass.hpp"
#include "material_colors.hpp"
#include "model/color_rules.hpp"
#include "property_colors.hpp"
#include "render_options.hpp"
#include "reply_lines.hpp"
#include "request_line.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace {

/// A line no rules file may have quoted back (see check_never_quoted).
constexpr const char SECRET[] = "qzxjv_secret";

/// The module's options and the rules file the inputs are written to.
struct Server {
    OptionTable options;
    RequestLineReader reader;
    std::string rules_path;
    int rules_fd = -1;
    Server() : options(define()), reader(options)
    {
        // a file by its path (the reader refuses links such as
        // /proc/self/fd/N), removed when the fuzzer exits
        static char path[] = "/tmp/fuzz_server_rules.XXXXXX";
        rules_fd = mkstemp(path);
        if (rules_fd < 0)
            std::abort();
        rules_path = path;
        std::atexit([] { unlink(path); });
    }
    static OptionTable define()
    {
        // GRASS's messages read their settings from a gisrc file: a
        // throw-away one (no location is opened: nothing here reads one)
        if (!std::getenv("GISRC")) {
            static char path[] = "/tmp/fuzz_server_gisrc.XXXXXX";
            const int fd = mkstemp(path);
            const char text[] = "GISDBASE: /tmp\nLOCATION_NAME: none\nMAPSET: none\n";
            if (fd < 0 || write(fd, text, sizeof text - 1) != ssize_t(sizeof text - 1))
                std::abort();
            close(fd);
            setenv("GISRC", path, 1);
            std::atexit([] { unlink(path); });
        }
        G_no_gisinit();
        G_set_program_name("r3.sbrt.render");
        G_define_module();
        return define_render_options();
    }
};

Server *server = nullptr;

/// One line of printable UTF-8 ending in its only line break.
void check_one_line(const std::string &line)
{
    if (line.empty() || line.back() != '\n')
        __builtin_trap();
    const std::string text = line.substr(0, line.size() - 1);
    if (!sbrt::is_valid_utf8(text) || sbrt::printable(text) != text)
        __builtin_trap();
}

/// Every error is answered as the server answers it.
void check_error(const std::exception &e)
{
    check_one_line(error_reply_line(e.what()));
}

/// The legend's lines: one line each, a channel's record three fields.
void check_legend(FuzzedDataProvider &in)
{
    sbrt::Material material;
    material.id = in.ConsumeIntegral<int32_t>();
    material.label = in.ConsumeRandomLengthString(256);
    check_one_line(class_reply_line(material, {in.ConsumeIntegral<uint8_t>(), 0, 255}));
    sbrt::ChannelInfo info;
    info.name = in.ConsumeRandomLengthString(128);
    info.unit = in.ConsumeRandomLengthString(64);
    info.long_name = in.ConsumeRandomLengthString(256);
    info.min = in.ConsumeFloatingPoint<double>();
    info.max = in.ConsumeFloatingPoint<double>();
    info.scale = in.ConsumeFloatingPoint<double>();
    info.offset = in.ConsumeFloatingPoint<double>();
    const std::string line = channel_reply_line(info);
    check_one_line(line);
    // "least greatest name|unit|long name": the record after two numbers
    size_t record = line.find(' ');
    record = record == std::string::npos ? record : line.find(' ', record + 1);
    if (record == std::string::npos ||
        std::count(line.begin() + long(record), line.end(), '|') != 2)
        __builtin_trap();
}

/// A rules file's error names the line, never quotes it: the secret line
/// after the input is refused (it is no rule) without being shown.
void check_never_quoted(const std::string &rules)
{
    try {
        sbrt::parse_color_rules(rules + "\n" + SECRET + " 1:2:3 " + SECRET + "\n",
                                "rules=fuzz");
    }
    catch (const sbrt::Error &e) {
        if (std::string(e.what()).find(SECRET) != std::string::npos)
            __builtin_trap();
        return;
    }
    __builtin_trap(); // the secret line is no rule
}

/// The rules as rules= of a request recolours the materials, and as
/// property_color= makes a property's ramp.
void apply_rules(const RenderRequest &asked, FuzzedDataProvider &in)
{
    sbrt::Model model;
    std::vector<sbrt::Material> &materials = model.materials();
    materials.resize(1 + in.ConsumeIntegralInRange<size_t>(0, 6));
    for (size_t i = 1; i < materials.size(); ++i)
        materials[i].id = in.ConsumeIntegral<int32_t>();
    RenderRequest request = asked;
    if (request.color.empty())
        request.rules = server->rules_path;
    try {
        apply_color_option(request, model.materials());
    }
    catch (const sbrt::Error &e) {
        check_error(e);
    }
    // a range as property_range makes it: finite, low below high
    const double low = in.ConsumeFloatingPointInRange<double>(-1e12, 1e12);
    const double high = low + in.ConsumeFloatingPointInRange<double>(1e-6, 1e12);
    try {
        const sbrt::ColorRamp ramp = property_ramp(server->rules_path, low, high);
        ramp.rgb_at((low + high) / 2);
    }
    catch (const sbrt::Error &e) {
        check_error(e);
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    server = new Server();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzedDataProvider in(data, size);
    // the request line, read as the server reads it
    const std::string line = in.ConsumeRandomLengthString(1024);
    RenderRequest request;
    try {
        const RequestLine read = server->reader.read(line);
        request = read.request;
    }
    catch (const sbrt::Error &e) {
        check_error(e);
    }
    check_legend(in);
    // the rules file: what is left
    const size_t count = in.ConsumeIntegralInRange<size_t>(0, 8);
    std::vector<uint8_t> numbers = in.ConsumeBytes<uint8_t>(count * 4 + 24);
    const std::string rules = in.ConsumeRemainingBytesAsString();
    check_never_quoted(rules);
    if (ftruncate(server->rules_fd, 0) != 0 ||
        pwrite(server->rules_fd, rules.data(), rules.size(), 0) != ssize_t(rules.size()))
        std::abort();
    FuzzedDataProvider values(numbers.data(), numbers.size());
    apply_rules(request, values);
    return 0;
}
