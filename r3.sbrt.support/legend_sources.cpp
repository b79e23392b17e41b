/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Labels and colours from GRASS tables, rules and maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "legend_sources.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>

#include "grass.hpp"
#include "model/legend_rules.hpp"
#include "util/error.hpp"

namespace {

/// The smallest and largest class id (materials has at least one class).
void id_range(const std::vector<sbrt::Material> &materials, CELL &low, CELL &high)
{
    low = high = materials[1].id;
    for (size_t i = 1; i < materials.size(); ++i) {
        low = std::min(low, materials[i].id);
        high = std::max(high, materials[i].id);
    }
}

/// Every class `colors` has a rule for gets that colour.
void take_colors(struct Colors *colors, std::vector<sbrt::Material> &materials)
{
    for (size_t i = 1; i < materials.size(); ++i) {
        int red, green, blue;
        CELL id = materials[i].id;
        if (!Rast_get_c_color(&id, &red, &green, &blue, colors))
            continue; // no rule for this class: it keeps its colour
        materials[i].red = uint8_t(red);
        materials[i].green = uint8_t(green);
        materials[i].blue = uint8_t(blue);
        materials[i].has_color = true;
    }
}

/// Reads colour rules line by line for Rast_read_color_rules, so that a
/// bad line is reported with the file and its number (GRASS's own reader
/// names neither).
struct RuleReader {
    FILE *file;
    const char *name;
    int line = 0;
};

int read_rule(void *closure, DCELL min, DCELL max, DCELL *value, int *red,
              int *green, int *blue, int *norm, int *nval, int *dflt)
{
    RuleReader *reader = static_cast<RuleReader *>(closure);
    char buffer[1024];
    *norm = *nval = *dflt = 0;
    while (std::fgets(buffer, sizeof buffer, reader->file)) {
        ++reader->line;
        buffer[std::strcspn(buffer, "\r\n")] = '\0';
        G_strip(buffer);
        if (*buffer == '\0' || *buffer == '#')
            continue;
        if (std::strcmp(buffer, "end") == 0)
            return 0;
        const int status =
            Rast_parse_color_rule(min, max, buffer, value, red, green, blue, norm, nval, dflt);
        if (status != 0)
            G_fatal_error(_("rules=%s line %d: %s (<%s>); a line is 'value colour', "
                            "the colour r:g:b or a name such as red"),
                          reader->name, reader->line, Rast_parse_color_rule_error(status),
                          buffer);
        return 1;
    }
    return 0;
}

} // namespace

void colors_from_table(const char *name, std::vector<sbrt::Material> &materials)
{
    CELL low, high;
    id_range(materials, low, high);
    if (low == high)
        ++high; // Rast_make_colors needs a range
    struct Colors colors;
    Rast_make_colors(&colors, name, low, high); // the option lists the names
    take_colors(&colors, materials);
    Rast_free_colors(&colors);
}

void colors_from_rules(const char *file, std::vector<sbrt::Material> &materials)
{
    CELL low, high;
    id_range(materials, low, high);
    const bool standard_input = std::strcmp(file, "-") == 0;
    FILE *in = standard_input ? stdin : std::fopen(file, "r");
    if (!in)
        G_fatal_error(_("rules=%s: unable to open this file"), file);
    RuleReader reader{in, file};
    struct Colors colors;
    Rast_init_colors(&colors);
    const int read = Rast_read_color_rules(&colors, low, high, read_rule, &reader);
    if (!standard_input)
        std::fclose(in);
    if (!read)
        G_fatal_error(_("rules=%s: no colour rules in it"), file);
    take_colors(&colors, materials);
    Rast_free_colors(&colors);
}

void legend_from_map(const char *name, bool three_d, std::vector<sbrt::Material> &materials)
{
    const char *mapset = three_d ? G_find_raster3d(name, "") : G_find_raster2(name, "");
    if (!mapset)
        G_fatal_error(_("%s=%s: map not found"), three_d ? "raster_3d" : "raster", name);
    struct Colors colors;
    const int have_colors = three_d ? Rast3d_read_colors(name, mapset, &colors)
                                    : Rast_read_colors(name, mapset, &colors);
    if (have_colors >= 0) {
        take_colors(&colors, materials);
        Rast_free_colors(&colors);
    }
    struct Categories cats;
    const int have_cats = three_d ? Rast3d_read_cats(name, mapset, &cats)
                                  : Rast_read_cats(name, mapset, &cats);
    if (have_cats == 0) {
        for (size_t i = 1; i < materials.size(); ++i) {
            CELL id = materials[i].id;
            const char *label = Rast_get_c_cat(&id, &cats);
            if (label && *label)
                materials[i].label = label;
        }
        Rast_free_cats(&cats);
    }
    if (have_colors < 0 && have_cats != 0)
        G_fatal_error(_("<%s> has neither a colour table nor categories"), name);
}

void labels_from_rules(const char *file, std::vector<sbrt::Material> &materials)
{
    std::vector<sbrt::ClassStyle> rules;
    try {
        if (std::strcmp(file, "-") == 0)
            rules = sbrt::parse_category_rules(std::cin, "labels=-");
        else {
            std::ifstream in(file);
            if (!in)
                G_fatal_error(_("labels=%s: unable to open this file"), file);
            rules = sbrt::parse_category_rules(in, std::string("labels=") + file);
        }
    }
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", e.what());
    }
    sbrt::apply_styles(materials, rules);
}
