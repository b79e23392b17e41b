/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Text from untrusted places (a file's attributes, another
 *            mapset's labels, a request) made safe for where it goes: valid
 *            UTF-8 for figures and files, no control characters for a
 *            terminal, one shell word for `eval $(... -g)`, a byte budget
 *            for GRASS's fixed-size fields
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_UTIL_SAFE_TEXT_HPP
#define SBRT_UTIL_SAFE_TEXT_HPP

#include <cstddef>
#include <string>
#include <string_view>

namespace sbrt {

/// \brief True when `text` is well-formed UTF-8 (RFC 3629: no overlong forms,
/// no surrogates, nothing past U+10FFFF).
bool is_valid_utf8(std::string_view text);

/// \brief `text` as valid UTF-8: each byte that starts no well-formed
/// sequence becomes U+FFFD (the replacement character), the rest is kept.
std::string valid_utf8(std::string_view text);

/// \brief `text` fit for a terminal or a one-line field: valid UTF-8 with
/// every control character (C0, DEL and C1; tab and line breaks too)
/// replaced by U+FFFD, so that no escape sequence reaches a terminal.
std::string printable(std::string_view text);

/// \brief As printable, but line breaks ('\n') are kept: a message of
/// several lines that quotes untrusted text.
std::string printable_lines(std::string_view text);

/// \brief `text` as one word a POSIX shell reads back unchanged and never
/// runs: as it is when made only of characters with no meaning to the
/// shell (letters, digits and _ . , : / + % @ = -), else single-quoted with
/// each ' written '\''. Safe under `eval $(...)` and `eval "$(...)"`. The
/// text is made printable first (a newline in a value would end the line).
std::string shell_word(std::string_view text);

/// \brief `text` as one field of a record of key=value fields joined by
/// '|' (a channel line of -g): printable, each '|' written U+00A6 (broken
/// bar), so that splitting the record at '|' finds its fields.
std::string record_field(std::string_view text);

/// \brief `text` as one field of a CSV line (RFC 4180): printable (a
/// label's escape sequence must not reach a terminal that shows the file),
/// quoted where it holds `separator` or a quote, each quote doubled.
std::string csv_field(std::string_view text, char separator = ',');

/// \brief JSON text `dumped` (as a JSON library writes it, valid UTF-8)
/// with DEL and the C1 controls (U+0080..U+009F, CSI among them, which
/// some terminals obey in UTF-8) escaped as \u007f..\u009f: libraries
/// escape only U+0000..U+001F, and JSON printed to a terminal must not
/// drive it. Both occur only inside strings, where the escape means the
/// same character.
std::string escape_json_controls(std::string_view dumped);

/// \brief The longest prefix of valid UTF-8 `text` of at most `max_bytes`
/// bytes that ends on a character boundary; "..." ends it when it was cut
/// and there is room for it.
std::string fit_bytes(std::string_view text, std::size_t max_bytes);

} // namespace sbrt

#endif
