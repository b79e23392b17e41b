/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The modules' errors as GRASS's fatal error
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "module_errors.hpp"

#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "grass.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt_grass {

namespace {

/// What a module printed must have reached standard output: a full disk or
/// a closed pipe is an error, not success (issue 48, item 11).
void check_standard_output()
{
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    if (flushed && !std::ferror(stdout))
        return;
    const int cause = errno;
    G_fatal_error(_("Cannot write to standard output: %s; check the disk or the program "
                    "reading it"),
                  cause ? std::strerror(cause) : _("a write failed"));
}

} // namespace

void fail_with(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    char *text = nullptr;
    G_vasprintf(&text, format, args);
    va_end(args);
    const std::string message = text ? text : format;
    G_free(text);
    throw sbrt::Error(message);
}

void run_reporting_errors(const char *doing, const std::string &subject,
                          const char *memory_hint, const std::function<void()> &job)
{
    try {
        job();
    }
    // messages quote untrusted text (another mapset's channel names and
    // units, a file's attributes): no control character reaches a terminal
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", sbrt::printable_lines(e.what()).c_str());
    }
    catch (const std::bad_alloc &) {
        G_fatal_error(_("Out of memory while %s <%s>: %s"), doing, subject.c_str(),
                      memory_hint);
    }
    catch (const std::exception &e) {
        G_fatal_error(_("Failed while %s <%s>: %s"), doing, subject.c_str(),
                      sbrt::printable_lines(e.what()).c_str());
    }
    check_standard_output();
}

} // namespace sbrt_grass
