/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Where new labels and colours come from: a GRASS colour table,
 *            colour rules, another map's colours and labels, category
 *            rules, a survey preset
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SUPPORT_LEGEND_SOURCES_HPP
#define R3_SBRT_SUPPORT_LEGEND_SOURCES_HPP

#include <string>
#include <vector>

#include "model/legend_rules.hpp"
#include "model/model.hpp"

/// \brief A rules file read whole (before the SBRT is locked, so that a
/// slow standard input holds up no other change): `file` as given, for
/// messages, and its text.
struct RulesText {
    std::string file;
    std::string text;
};

/// Colours of every class from GRASS colour table `name` (viridis, ...)
/// stretched over the range of the class ids, as r3.colors color= does.
void colors_from_table(const char *name, std::vector<sbrt::Material> &materials);
/// Colours from GRASS colour rules, as r3.colors rules= reads them; a bad
/// line is a fatal error naming it. Classes no rule covers keep their
/// colours. Says how many lines reached a class, and warns of those that
/// named none of SBRT `sbrt_name`.
void colors_from_rules(const RulesText &rules, const char *sbrt_name,
                       std::vector<sbrt::Material> &materials);
/// Colours and labels of raster map `name` (2D, or 3D with `three_d`):
/// classes the map has no colour or label for keep theirs. Labels are
/// made valid UTF-8.
void legend_from_map(const char *name, bool three_d, std::vector<sbrt::Material> &materials);
/// Category rules "id:label" of `rules` (a fatal error names a bad line),
/// their labels made valid UTF-8.
std::vector<sbrt::ClassStyle> parse_label_rules(const RulesText &rules);
/// Sets the labels of `label_rules` (read from `file`); says how many
/// lines reached a class, and warns of those that named none of SBRT
/// `sbrt_name`.
void apply_label_rules(const std::vector<sbrt::ClassStyle> &label_rules, const char *file,
                       const char *sbrt_name, std::vector<sbrt::Material> &materials);

#endif
