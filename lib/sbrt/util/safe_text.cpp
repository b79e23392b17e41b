/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Untrusted text made safe for figures, terminals, shells and
 *            GRASS's fixed-size fields
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/safe_text.hpp"

#include <cstdint>
#include <cstdio>

namespace sbrt {

namespace {

constexpr std::string_view replacement = "\xEF\xBF\xBD"; // U+FFFD

/// The length of the well-formed UTF-8 sequence at text[at] (1-4), or 0
/// where none starts there (RFC 3629, Table 3-7 of the Unicode standard).
std::size_t sequence_length(std::string_view text, std::size_t at)
{
    const auto byte = [&](std::size_t i) { return uint8_t(text[at + i]); };
    const std::size_t left = text.size() - at;
    const uint8_t b0 = byte(0);
    if (b0 < 0x80)
        return 1;
    std::size_t length;
    uint8_t low = 0x80, high = 0xBF; // the second byte's range
    if (b0 >= 0xC2 && b0 <= 0xDF)
        length = 2;
    else if (b0 >= 0xE0 && b0 <= 0xEF) {
        length = 3;
        if (b0 == 0xE0)
            low = 0xA0; // no overlong form
        if (b0 == 0xED)
            high = 0x9F; // no surrogates
    }
    else if (b0 >= 0xF0 && b0 <= 0xF4) {
        length = 4;
        if (b0 == 0xF0)
            low = 0x90;
        if (b0 == 0xF4)
            high = 0x8F; // nothing past U+10FFFF
    }
    else
        return 0;
    if (left < length || byte(1) < low || byte(1) > high)
        return 0;
    for (std::size_t i = 2; i < length; ++i)
        if (byte(i) < 0x80 || byte(i) > 0xBF)
            return 0;
    return length;
}

/// C0, DEL and the C1 controls (U+0080-U+009F, 0xC2 0x80-0x9F in UTF-8).
bool is_control(std::string_view text, std::size_t at, std::size_t length)
{
    const uint8_t b0 = uint8_t(text[at]);
    if (length == 1)
        return b0 < 0x20 || b0 == 0x7F;
    return length == 2 && b0 == 0xC2 && uint8_t(text[at + 1]) <= 0x9F;
}

/// Characters with no meaning to a POSIX shell, in or out of an assignment.
bool is_shell_plain(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '.' || c == ',' || c == ':' || c == '/' || c == '+' ||
           c == '%' || c == '@' || c == '=' || c == '-';
}

template <typename Keep>
std::string filtered(std::string_view text, Keep keep)
{
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = sequence_length(text, at);
        if (length == 0) {
            out += replacement;
            ++at;
            continue;
        }
        if (keep(at, length))
            out.append(text.substr(at, length));
        else
            out += replacement;
        at += length;
    }
    return out;
}

} // namespace

bool is_valid_utf8(std::string_view text)
{
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = sequence_length(text, at);
        if (length == 0)
            return false;
        at += length;
    }
    return true;
}

std::string valid_utf8(std::string_view text)
{
    return filtered(text, [](std::size_t, std::size_t) { return true; });
}

std::string printable(std::string_view text)
{
    return filtered(text, [&](std::size_t at, std::size_t length) {
        return !is_control(text, at, length);
    });
}

std::string printable_lines(std::string_view text)
{
    return filtered(text, [&](std::size_t at, std::size_t length) {
        return text[at] == '\n' || !is_control(text, at, length);
    });
}

std::string shell_word(std::string_view text)
{
    const std::string safe = printable(text);
    bool plain = true;
    for (const char c : safe)
        plain = plain && is_shell_plain(c);
    if (plain)
        return safe;
    std::string word = "'";
    for (const char c : safe) {
        if (c == '\'')
            word += "'\\''";
        else
            word += c;
    }
    return word + "'";
}

std::string record_field(std::string_view text)
{
    std::string field;
    for (const char c : printable(text)) {
        if (c == '|')
            field += "\xC2\xA6";
        else
            field += c;
    }
    return field;
}

std::string csv_field(std::string_view text, char separator)
{
    const std::string safe = printable(text);
    if (safe.find(separator) == std::string::npos && safe.find('"') == std::string::npos)
        return safe;
    std::string field = "\"";
    for (const char c : safe)
        field += c == '"' ? std::string("\"\"") : std::string(1, c);
    return field + "\"";
}

std::string escape_json_controls(std::string_view dumped)
{
    std::string out;
    out.reserve(dumped.size());
    char escaped[8];
    for (std::size_t i = 0; i < dumped.size(); ++i) {
        const auto c = static_cast<unsigned char>(dumped[i]);
        const auto next = i + 1 < dumped.size() ? static_cast<unsigned char>(dumped[i + 1]) : 0;
        if (c == 0x7f)
            out += "\\u007f";
        else if (c == 0xc2 && next >= 0x80 && next <= 0x9f) {
            // in valid UTF-8 the byte C2 always leads a character of two
            std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(next));
            out += escaped;
            ++i;
        }
        else
            out += char(c);
    }
    return out;
}

std::string fit_bytes(std::string_view text, std::size_t max_bytes)
{
    if (text.size() <= max_bytes)
        return std::string(text);
    const std::string_view ellipsis = "...";
    const std::size_t budget = max_bytes >= 2 * ellipsis.size() ? max_bytes - ellipsis.size()
                                                                : max_bytes;
    std::size_t end = 0;
    while (end < text.size()) {
        const std::size_t length = sequence_length(text, end);
        const std::size_t step = length ? length : 1;
        if (end + step > budget)
            break;
        end += step;
    }
    std::string out(text.substr(0, end));
    if (budget != max_bytes)
        out += ellipsis;
    return out;
}

} // namespace sbrt
