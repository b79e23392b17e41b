/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Errors of a render request as values
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "request_error.hpp"

#include <cstdarg>
#include <cstdio>
#include <vector>

#include "util/error.hpp"

namespace {

/// The longest message a request's error keeps (a value quoted in it may
/// be megabytes long; a reply line stays readable).
constexpr size_t MESSAGE_LIMIT = 2000;

} // namespace

std::string shortened(const std::string &text, size_t limit)
{
    if (text.size() <= limit)
        return text;
    return text.substr(0, limit) + "... (" + std::to_string(text.size() - limit) +
           " more characters)";
}

void bad_request(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    const int length = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::vector<char> text(size_t(length > 0 ? length : 0) + 1);
    std::vsnprintf(text.data(), text.size(), format, again);
    va_end(again);
    throw sbrt::Error(shortened(text.data(), MESSAGE_LIMIT));
}
