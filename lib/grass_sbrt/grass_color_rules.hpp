/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Colour rules files as GRASS colour tables: the file is read and
 *            checked by lib/sbrt (model/color_rules.hpp), and only its
 *            checked rules reach GRASS, so that GRASS's own reader (which
 *            ends the process on a bad line and prints it) never sees a file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRASS_COLOR_RULES_HPP
#define SBRT_GRASS_COLOR_RULES_HPP

#include "grass.hpp"
#include "model/color_rules.hpp"

/// Fills `colors` (initialised here) with `rules` over the range [low,
/// high] of their % values, as Rast_read_color_rules does with a file's
/// lines: each rule to the next, nv and default colours. Never fails.
void set_grass_colors(const sbrt::ColorRules &rules, double low, double high,
                      struct Colors *colors);

#endif
