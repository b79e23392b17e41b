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

#include "model/model.hpp"

/// Colours of every class from GRASS colour table `name` (viridis, ...)
/// stretched over the range of the class ids, as r3.colors color= does.
void colors_from_table(const char *name, std::vector<sbrt::Material> &materials);
/// Colours from GRASS colour rules (file, '-' for standard input), as
/// r3.colors rules= reads them; a bad line is a fatal error naming it.
/// Classes no rule covers keep their colours.
void colors_from_rules(const char *file, std::vector<sbrt::Material> &materials);
/// Colours and labels of raster map `name` (2D, or 3D with `three_d`):
/// classes the map has no colour or label for keep theirs.
void legend_from_map(const char *name, bool three_d, std::vector<sbrt::Material> &materials);
/// Labels from category rules "id:label" (file, '-' for standard input).
void labels_from_rules(const char *file, std::vector<sbrt::Material> &materials);

#endif
