/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   format= and separator= of every module that prints, and the
 *            CSV and JSON records they choose
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "output_format.hpp"

#include <cstring>

#include <nlohmann/json.hpp>

extern "C" {
#include <grass/version.h>
}

#include "util/safe_text.hpp"

// GRASS 8.4 added the standard format= (G_OPT_F_FORMAT, lib/gis/
// parser_standard_options.c); 8.2 has none
#if GRASS_VERSION_MAJOR > 8 || (GRASS_VERSION_MAJOR == 8 && GRASS_VERSION_MINOR >= 4)
#define SBRT_HAVE_G_OPT_F_FORMAT 1
#endif

namespace sbrt_grass {

namespace {

struct FormatName {
    OutputFormat format;
    const char *name, *description;
};

// the descriptions GRASS 8.4's modules give the formats (r.info, v.info)
constexpr FormatName FORMAT_NAMES[] = {
    {OutputFormat::plain, "plain", "Human readable text output"},
    {OutputFormat::shell, "shell", "Shell script style text output"},
    {OutputFormat::json, "json", "JSON (JavaScript Object Notation)"},
    {OutputFormat::csv, "csv", "CSV (Comma Separated Values)"},
};

const FormatName &name_of(OutputFormat format)
{
    for (const FormatName &n : FORMAT_NAMES)
        if (n.format == format)
            return n;
    G_fatal_error("output format %d has no name", int(format));
}

} // namespace

Option *define_format_option(const std::vector<OutputFormat> &formats, bool required)
{
#ifdef SBRT_HAVE_G_OPT_F_FORMAT
    Option *o = G_define_standard_option(G_OPT_F_FORMAT);
#else
    Option *o = G_define_option();
    o->key = "format";
    o->type = TYPE_STRING;
    o->key_desc = "name";
    o->label = _("Output format");
#endif
    std::string options, descriptions;
    for (const OutputFormat format : formats) {
        const FormatName &n = name_of(format);
        options += (options.empty() ? "" : ",") + std::string(n.name);
        descriptions += std::string(n.name) + ";" + _(n.description) + ";";
    }
    // the parser keeps the pointers for the run
    o->options = G_store(options.c_str());
    o->descriptions = G_store(descriptions.c_str());
    o->required = required ? YES : NO;
    o->answer = required ? G_store(name_of(formats.front()).name) : nullptr;
    return o;
}

Option *define_separator_option()
{
    Option *o = G_define_standard_option(G_OPT_F_SEP);
    o->answer = nullptr;
    o->label = _("Field separator of format=csv (default: comma)");
    o->description = _("Special characters: pipe, comma, space, tab, or one character");
    return o;
}

OutputFormat read_output_format(const Option *format, const Flag *shell)
{
    OutputFormat asked = OutputFormat::none;
    if (format->answer)
        for (const FormatName &n : FORMAT_NAMES)
            if (std::strcmp(format->answer, n.name) == 0)
                asked = n.format;
    if (!shell || !shell->answer)
        return asked;
    if (asked != OutputFormat::none && asked != OutputFormat::plain &&
        asked != OutputFormat::shell)
        G_fatal_error(_("-g prints in shell script style (as format=shell does), which "
                        "format=%s contradicts: give -g or format=, not both"),
                      format->answer);
    return OutputFormat::shell;
}

char read_csv_separator(const Option *separator, OutputFormat format)
{
    if (!separator->answer)
        return ',';
    if (format != OutputFormat::csv) {
        G_warning(_("separator=%s is for format=csv: ignored"), separator->answer);
        return ',';
    }
    char *text = G_option_to_separator(separator);
    const std::string chosen = text;
    G_free(text);
    if (chosen.size() != 1)
        G_fatal_error(_("separator=%s: a csv field ends at one character; give comma, "
                        "tab, space, pipe or a single character"),
                      separator->answer);
    if (chosen[0] == '\n' || chosen[0] == '\r' || chosen[0] == '"')
        G_fatal_error(_("separator=%s: a csv record is one line with fields quoted by '\"', "
                        "so neither a line end nor a quote can part its fields; give "
                        "comma, tab, space or pipe"),
                      separator->answer);
    return chosen[0];
}

std::string csv_record(const std::vector<std::string> &fields, char separator)
{
    std::string line;
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i)
            line += separator;
        line += sbrt::csv_field(fields[i], separator);
    }
    return line + "\n";
}

std::string json_text(const nlohmann::ordered_json &value, int indent)
{
    return sbrt::escape_json_controls(
        value.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

} // namespace sbrt_grass
