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

/// \brief A GRASS colour table (initialised), freed whole with its owner:
/// Rast_free_colors of GRASS 8.2 (lib/raster/color_free.c) leaves the
/// floating-point lookup that Rast__organize_colors builds on the first
/// lookup, a leak per table in a long-running view server.
class GrassColors {
public:
    GrassColors() { Rast_init_colors(&colors_); }
    ~GrassColors();
    GrassColors(const GrassColors &) = delete;
    GrassColors &operator=(const GrassColors &) = delete;

    struct Colors *get() { return &colors_; }

private:
    struct Colors colors_;
};

/// Fills `colors` (as Rast_init_colors left it) with `rules` over the range [low,
/// high] of their % values, as Rast_read_color_rules does with a file's
/// lines: each rule to the next, nv and default colours. Never fails.
void set_grass_colors(const sbrt::ColorRules &rules, double low, double high,
                      struct Colors *colors);

#endif
