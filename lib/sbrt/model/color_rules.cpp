/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Colour rules files read and checked line by line
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/color_rules.hpp"

#include <charconv>
#include <cmath>

#include "util/user_file.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt {

namespace {

/// GRASS's colour names and colours (lib/gis/color_str.c).
struct NamedColor {
    const char *name;
    Rgb rgb;
};
constexpr NamedColor NAMED_COLORS[] = {
    {"black", {0, 0, 0}},       {"red", {255, 0, 0}},       {"green", {0, 255, 0}},
    {"blue", {0, 0, 255}},      {"yellow", {255, 255, 0}},  {"cyan", {0, 255, 255}},
    {"magenta", {255, 0, 255}}, {"white", {255, 255, 255}}, {"grey", {128, 128, 128}},
    {"gray", {128, 128, 128}},  {"orange", {255, 128, 0}},  {"aqua", {100, 128, 255}},
    {"indigo", {0, 128, 255}},  {"violet", {128, 0, 255}},  {"purple", {128, 0, 255}},
    {"brown", {180, 77, 25}},
};

/// What follows "line N:" when a line is not a rule.
constexpr const char *SYNTAX =
    "not a colour rule 'value colour' (value a number, a percentage such as 50%, nv "
    "or default; colour red:green:blue with components 0-255, #RRGGBB or a colour "
    "name such as red or grey)";

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && is_blank(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && is_blank(text.back()))
        text.remove_suffix(1);
    return text;
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; }

bool same_words(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i]))
            return false;
    return true;
}

/// A finite number that is all of `text` (an optional leading '+').
std::optional<double> number(std::string_view text)
{
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    if (text.empty() || text.front() == '+')
        return std::nullopt;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

int hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    c = lower(c);
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/// A component 0-255: digits only, all of `text`.
std::optional<uint8_t> component(std::string_view text)
{
    if (text.empty() || text.size() > 3)
        return std::nullopt;
    int value = 0;
    for (char c : text) {
        if (c < '0' || c > '9')
            return std::nullopt;
        value = value * 10 + (c - '0');
    }
    if (value > 255)
        return std::nullopt;
    return uint8_t(value);
}

bool is_separator(char c) { return c == ',' || c == ':' || c == ';' || is_blank(c); }

/// R:G:B (G_str_to_color's separators, one or more), #RRGGBB or a name.
std::optional<Rgb> color(std::string_view text)
{
    if (text.size() == 7 && text.front() == '#') {
        Rgb rgb{};
        for (int i = 0; i < 3; ++i) {
            const int high = hex_digit(text[size_t(1 + 2 * i)]);
            const int low = hex_digit(text[size_t(2 + 2 * i)]);
            if (high < 0 || low < 0)
                return std::nullopt;
            rgb[size_t(i)] = uint8_t(high * 16 + low);
        }
        return rgb;
    }
    if (std::optional<Rgb> named = named_color(text))
        return named;
    Rgb rgb{};
    for (int i = 0; i < 3; ++i) {
        if (i > 0) {
            // one or more separators between components
            size_t n = 0;
            while (n < text.size() && is_separator(text[n]))
                ++n;
            if (n == 0)
                return std::nullopt;
            text.remove_prefix(n);
        }
        size_t n = 0;
        while (n < text.size() && !is_separator(text[n]))
            ++n;
        const std::optional<uint8_t> c = component(text.substr(0, n));
        if (!c)
            return std::nullopt;
        rgb[size_t(i)] = *c;
        text.remove_prefix(n);
    }
    if (!text.empty())
        return std::nullopt;
    return rgb;
}

/// Reads one line (trimmed, not blank, not a comment) into `rules`.
void read_line(std::string_view line, size_t number_of_line, const std::string &what,
               ColorRules &rules)
{
    size_t split = 0;
    while (split < line.size() && !is_blank(line[split]))
        ++split;
    const std::string_view value = line.substr(0, split);
    const std::string_view colour = trimmed(line.substr(split));
    if (colour.empty())
        fail(what, ": line ", number_of_line, ": ", SYNTAX);
    const std::optional<Rgb> rgb = color(colour);
    if (!rgb)
        fail(what, ": line ", number_of_line,
             ": the colour is not red:green:blue with components 0-255, #RRGGBB or a "
             "colour name (black, white, red, green, blue, yellow, cyan, magenta, grey, "
             "orange, aqua, indigo, violet, purple, brown)");
    if (same_words(value, "default")) {
        rules.default_color = *rgb;
        return;
    }
    if (same_words(value, "nv")) {
        rules.null_color = *rgb;
        return;
    }
    ColorRule rule;
    rule.rgb = *rgb;
    rule.percent = !value.empty() && value.back() == '%';
    const std::optional<double> x =
        number(rule.percent ? value.substr(0, value.size() - 1) : value);
    if (!x)
        fail(what, ": line ", number_of_line,
             ": the value is not a finite number, a percentage such as 50%, nv or default");
    if (rule.percent && (*x < 0 || *x > 100))
        fail(what, ": line ", number_of_line, ": the percentage is not between 0 and 100");
    rule.value = *x;
    rules.rules.push_back(rule);
}

} // namespace

std::optional<Rgb> named_color(std::string_view name)
{
    for (const NamedColor &c : NAMED_COLORS)
        if (same_words(name, c.name))
            return c.rgb;
    return std::nullopt;
}

ColorRules parse_color_rules(std::string_view text, const std::string &what_given)
{
    const std::string what = printable(what_given);
    ColorRules rules;
    size_t number_of_line = 0;
    while (!text.empty()) {
        ++number_of_line;
        const size_t end = text.find('\n');
        const std::string_view line =
            trimmed(end == std::string_view::npos ? text : text.substr(0, end));
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        if (line.empty() || line.front() == '#')
            continue;
        if (same_words(line, "end")) // as r.colors' rules= ends
            break;
        read_line(line, number_of_line, what, rules);
    }
    if (rules.rules.empty())
        fail(what, ": no colour rules (lines 'value colour', e.g. '0% blue' and "
                   "'100% red')");
    return rules;
}

ColorRules read_color_rules_file(const std::string &path, const std::string &what)
{
    const std::string named = printable(what);
    // a FIFO, a device or a directory is refused at once, the size bounded
    const std::string text = read_user_file(path, MAX_COLOR_RULES_BYTES, named);
    return parse_color_rules(text, named);
}

ColorRules read_color_rules_stream(std::FILE *stream, const std::string &what)
{
    const std::string named = printable(what);
    return parse_color_rules(read_to_end(fileno(stream), MAX_COLOR_RULES_BYTES, named), named);
}

} // namespace sbrt
