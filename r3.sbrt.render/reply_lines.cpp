/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The view server's reply lines, safe whatever the SBRT or the
 *            request holds
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "reply_lines.hpp"

#include <algorithm>
#include <cstdio>

#include "request_error.hpp"
#include "util/safe_text.hpp"

namespace {

/// The longest error reply (a message quotes values of the request).
constexpr size_t MAX_ERROR_REPLY = 2000;

} // namespace

std::string class_reply_line(const sbrt::Material &material,
                             const std::array<uint8_t, 3> &rgb)
{
    char head[64];
    std::snprintf(head, sizeof head, "%d %d %d %d ", material.id, rgb[0], rgb[1], rgb[2]);
    // no line break, carriage return, NUL or escape sequence in a label
    return head + sbrt::printable(material.label) + "\n";
}

std::string channel_reply_line(const sbrt::ChannelInfo &info)
{
    const double a = info.physical(float(info.min)), b = info.physical(float(info.max));
    char head[64];
    std::snprintf(head, sizeof head, "%.9g %.9g ", std::min(a, b), std::max(a, b));
    // the viewer splits the record at '|': each field printable, no '|'
    return head + sbrt::record_field(info.name) + "|" + sbrt::record_field(info.unit) + "|" +
           sbrt::record_field(info.long_name) + "\n";
}

std::string error_reply_line(const std::string &message)
{
    std::string line = shortened(message, MAX_ERROR_REPLY);
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    return "error " + sbrt::printable(line) + "\n";
}
