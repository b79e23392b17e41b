/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   format= and separator= of every module that prints, as GRASS
 *            8.4 defines them (G_OPT_F_FORMAT, G_OPT_F_SEP; format=shell
 *            beside the -g it replaces), and the records they choose:
 *            CSV lines quoted for the separator chosen, JSON written by
 *            nlohmann::json as valid UTF-8
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_OUTPUT_FORMAT_HPP
#define SBRT_OUTPUT_FORMAT_HPP

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "grass.hpp"

namespace sbrt_grass {

/// \brief What a module prints in; `none` where a module that prints
/// only on request (r3.sbrt.profile) is asked for nothing.
enum class OutputFormat { none, plain, shell, json, csv };

/// \brief format=: G_OPT_F_FORMAT where the GRASS built against has it
/// (8.4 and later), else an option of the same key, type and label;
/// `formats` are those the module offers, in GRASS's words. Required with
/// the first as default; with `required` false no default (nothing
/// printed unless asked).
Option *define_format_option(const std::vector<OutputFormat> &formats,
                             bool required = true);

/// \brief separator=: G_OPT_F_SEP for format=csv (GRASS's names pipe,
/// comma, space, tab or a character), no answer: comma, as r.what writes
/// csv.
Option *define_separator_option();

/// The format asked for: format='s answer, or shell with -g (`shell`, the
/// flag GRASS keeps while it moves to format=shell): -g with format=plain
/// (the default) or shell prints what format=shell prints; a fatal error
/// for -g with another format.
OutputFormat read_output_format(const Option *format, const Flag *shell = nullptr);

/// The csv separator of separator= (comma where it has no answer); a
/// fatal error for one that is no single character or one that a csv
/// record cannot hold (newline, carriage return, a quote); a warning where
/// it is given and `format` is no csv, which ignores it.
char read_csv_separator(const Option *separator, OutputFormat format);

/// \brief One csv line (RFC 4180): each field sbrt::csv_field (printable,
/// quoted where it holds the separator or a quote) and the line end.
std::string csv_record(const std::vector<std::string> &fields, char separator);

/// \brief `value` as JSON text by nlohmann::json: valid UTF-8 whatever
/// its strings hold (a byte that is no UTF-8 becomes U+FFFD instead of an
/// exception), nan and inf as null, control characters escaped (DEL and C1
/// too, which libraries leave raw); `indent` spaces a level, -1 one line.
std::string json_text(const nlohmann::ordered_json &value, int indent = 2);

} // namespace sbrt_grass

#endif
