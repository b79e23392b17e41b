/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Checked colour rules as a GRASS colour table
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "grass_color_rules.hpp"

GrassColors::~GrassColors()
{
    Rast__color_free_fp_lookup(&colors_.fixed);
    Rast__color_free_fp_lookup(&colors_.modular);
    Rast_free_colors(&colors_);
}

void set_grass_colors(const sbrt::ColorRules &rules, double low, double high,
                      struct Colors *colors)
{
    // as Rast_read_color_rules (lib/raster/color_rules.c) builds its table
    // (on a table just initialised: Rast_init_colors frees nothing)
    const std::vector<sbrt::ColorRule> &r = rules.rules;
    if (r.size() == 1)
        Rast_set_d_color(r[0].value_in(low, high), r[0].rgb[0], r[0].rgb[1], r[0].rgb[2],
                         colors);
    for (size_t i = 1; i < r.size(); ++i) {
        const DCELL a = r[i - 1].value_in(low, high), b = r[i].value_in(low, high);
        Rast_add_d_color_rule(&a, r[i - 1].rgb[0], r[i - 1].rgb[1], r[i - 1].rgb[2], &b,
                              r[i].rgb[0], r[i].rgb[1], r[i].rgb[2], colors);
    }
    if (rules.null_color)
        Rast_set_null_value_color((*rules.null_color)[0], (*rules.null_color)[1],
                                  (*rules.null_color)[2], colors);
    if (rules.default_color)
        Rast_set_default_color((*rules.default_color)[0], (*rules.default_color)[1],
                               (*rules.default_color)[2], colors);
}
