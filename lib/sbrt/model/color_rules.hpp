/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colour rules files (r.colors rules=) read as untrusted input:
 *            only a regular file of bounded size, every line checked before
 *            any rule is used; an error names the file and the line number,
 *            never the line's content (the path may name a file that is not
 *            a rules file at all, such as /etc/shadow)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLOR_RULES_HPP
#define SBRT_COLOR_RULES_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sbrt {

/// The largest colour rules file read (GRASS's tables are a few KiB).
constexpr size_t MAX_COLOR_RULES_BYTES = size_t(1) << 20;

using Rgb = std::array<uint8_t, 3>;

/// \brief One line "value colour" of a rules file.
struct ColorRule {
    double value = 0;     ///< finite; 0-100 where `percent`
    bool percent = false; ///< the value is a percentage of the range
    Rgb rgb{};

    /// The value over the range [low, high] (as GRASS reads a % value).
    double value_in(double low, double high) const
    {
        return percent ? low + (high - low) * (value / 100) : value;
    }
};

/// \brief The rules of a file in file order, and its nv and default
/// colours (the last of each when given twice, as GRASS keeps them).
struct ColorRules {
    std::vector<ColorRule> rules; ///< never empty once read
    std::optional<Rgb> null_color;
    std::optional<Rgb> default_color;
};

/// \brief The rules of `text`, GRASS's syntax (lib/raster/color_rules.c):
/// lines "value colour", value a number, a percentage (0-100%), "nv" or
/// "default"; colour R:G:B (or R G B, separators , : ; and blanks), #RRGGBB
/// or a GRASS colour name (red, grey, ...); blank lines and lines starting
/// with # are skipped; a line "end" ends the rules. Stricter than GRASS: the whole value and the whole
/// colour must parse, values must be finite. Throws sbrt::Error
/// "<what>: line N: <what is wrong>", never quoting the line; also where
/// no line is a rule. `what` names the source (e.g. "rules=/path").
ColorRules parse_color_rules(std::string_view text, const std::string &what);

/// \brief The rules of file `path` (a regular file, no FIFO, device or
/// symbolic link, at most MAX_COLOR_RULES_BYTES) as parse_color_rules
/// reads them; `what` names the option in messages.
ColorRules read_color_rules_file(const std::string &path, const std::string &what);

/// \brief The rules read from `stream` (standard input of rules=-) up to
/// its end, refused past MAX_COLOR_RULES_BYTES.
ColorRules read_color_rules_stream(std::FILE *stream, const std::string &what);

/// \brief The colour of GRASS colour name `name` (any case), none when it
/// is not one of GRASS's 16 names (lib/gis/color_str.c).
std::optional<Rgb> named_color(std::string_view name);

} // namespace sbrt

#endif
