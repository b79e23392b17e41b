/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Errors of a render request as values: the request's checks
 *            throw sbrt::Error with a GRASS-style message (printf format,
 *            translated); the command line turns it into G_fatal_error,
 *            the view server into an "error" reply after which it serves on
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_REQUEST_ERROR_HPP
#define R3_SBRT_REQUEST_ERROR_HPP

#include <string>

/// Throws sbrt::Error with the message `format` (printf) makes, cut to a
/// readable length (a request's value can be megabytes long).
[[noreturn]] void bad_request(const char *format, ...)
    __attribute__((format(printf, 1, 2)));

/// `text` cut to `limit` characters with "..." and the number left out
/// (values of a request quoted in a message).
std::string shortened(const std::string &text, size_t limit = 200);

#endif
