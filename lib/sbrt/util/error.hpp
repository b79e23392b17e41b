/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The single exception type of the SBRT library and check macros
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_ERROR_HPP
#define SBRT_ERROR_HPP

#include <sstream>
#include <stdexcept>
#include <string>

namespace sbrt {

/// \brief Every failure of the library: "where: what (value)".
class Error : public std::runtime_error {
public:
    explicit Error(const std::string &message) : std::runtime_error(message) {}
};

/// \brief Builds a message from stream-able pieces and throws sbrt::Error.
template <typename... Parts>
[[noreturn]] void fail(const Parts &...parts)
{
    std::ostringstream out;
    (out << ... << parts);
    throw Error(out.str());
}

} // namespace sbrt

/// Run-time check that prints both values when it fails.
#define SBRT_CHECK_EQ(a, b, where)                                           \
    do {                                                                     \
        if (!((a) == (b)))                                                   \
            ::sbrt::fail(where, ": check " #a " == " #b " failed (", (a),    \
                         " != ", (b), ")");                                  \
    } while (0)

#endif
