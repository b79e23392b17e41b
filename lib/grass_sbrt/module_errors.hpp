/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The one place where the modules turn what their work throws
 *            into GRASS's fatal error: a message, never an abort
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MODULE_ERRORS_HPP
#define SBRT_MODULE_ERRORS_HPP

#include <functional>
#include <string>

namespace sbrt_grass {

/// Runs a module's `job` (what main() does after G_parser), ending with
/// G_fatal_error on what it throws: an sbrt::Error's message as it is;
/// running out of memory as "Out of memory while <doing> <subject>: <hint>";
/// any other exception (one carried from a worker thread) as "Failed while
/// <doing> <subject>: <what>". Then what the job printed must have reached
/// standard output (flushed, no write failed): else a fatal error, so that
/// `module > /dev/full` never exits 0.
/// Throws sbrt::Error with the message a printf `format` makes: for the
/// translatable messages (`_("...")`) that modules throw to
/// run_reporting_errors or to the view server, which answers them.
[[noreturn]] void fail_with(const char *format, ...) __attribute__((format(printf, 1, 2)));

void run_reporting_errors(const char *doing, const std::string &subject,
                          const char *memory_hint, const std::function<void()> &job);

} // namespace sbrt_grass

#endif
