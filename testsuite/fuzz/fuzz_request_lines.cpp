/****************************************************************************
 * MODULE:    testsuite/fuzz (r3.sbrt addon)
 * PURPOSE:   libFuzzer target of the view server's protocol: each input is
 *            one request line, read as r3.sbrt.render --serve reads it
 *            (RequestLineReader: framing, verb, the module's options, the
 *            command line's checks) into a typed request or an sbrt::Error.
 *            A crash, a leak, undefined behaviour, a hang or an exit (a
 *            G_fatal_error that would end the server) fails it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <unistd.h>

#include <cstddef>
#include <cstdlib>
#include <cstdint>
#include <exception>
#include <string>

#include "grass.hpp"
#include "render_options.hpp"
#include "request_line.hpp"
#include "util/error.hpp"

namespace {

/// The module's options, defined once as main() defines them.
struct Protocol {
    OptionTable options;
    RequestLineReader reader;
    Protocol() : options(define()), reader(options) {}
    static OptionTable define()
    {
        // GRASS's messages read their settings from a gisrc file: a
        // throw-away one (no location is opened: nothing here reads one)
        if (!std::getenv("GISRC")) {
            static char path[] = "/tmp/fuzz_request_gisrc.XXXXXX";
            const int fd = mkstemp(path);
            const char text[] = "GISDBASE: /tmp\nLOCATION_NAME: none\nMAPSET: none\n";
            if (fd < 0 || write(fd, text, sizeof text - 1) != ssize_t(sizeof text - 1))
                std::abort();
            close(fd);
            setenv("GISRC", path, 1);
        }
        G_no_gisinit();
        G_set_program_name("r3.sbrt.render");
        G_define_module();
        return define_render_options();
    }
};

} // namespace

/// The options, defined before the first input: GRASS keeps (and partly
/// leaks) what G_define_standard_option allocates, once per process, as
/// in the module.
static Protocol *protocol = nullptr;

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
    protocol = new Protocol();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const std::string line(reinterpret_cast<const char *>(data), size);
    try {
        const RequestLine request = protocol->reader.read(line);
        // a request read whole holds what the server renders from
        if (request.verb == RequestLine::Verb::render && request.request.input.empty())
            __builtin_trap();
    }
    catch (const sbrt::Error &) {
        // answered with an error line: what the server does
    }
    return 0;
}
