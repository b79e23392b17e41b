/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Labels and colours from GRASS tables, rules and maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "legend_sources.hpp"

#include <algorithm>
#include <sstream>

#include "grass.hpp"
#include "grass_color_rules.hpp"
#include "rule_counts.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

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

/// Every class `colors` has a rule for gets that colour; returns how many
/// classes changed.
size_t take_colors(struct Colors *colors, std::vector<sbrt::Material> &materials)
{
    size_t changed = 0;
    for (size_t i = 1; i < materials.size(); ++i) {
        int red, green, blue;
        CELL id = materials[i].id;
        if (!Rast_get_c_color(&id, &red, &green, &blue, colors))
            continue; // no rule for this class: it keeps its colour
        sbrt::Material &m = materials[i];
        if (!m.has_color || m.red != red || m.green != green || m.blue != blue)
            ++changed;
        m.red = uint8_t(red);
        m.green = uint8_t(green);
        m.blue = uint8_t(blue);
        m.has_color = true;
    }
    return changed;
}

/// Says how many lines of `key`=`file` reached a class and `changed`
/// classes; a warning names the lines that reached none.
void report_counts(const char *key, const std::string &file, const char *sbrt_name,
                   const RuleCounts &counts, size_t changed,
                   const std::vector<int32_t> &ids)
{
    G_message(_("%s=%s: %zu of %zu lines applied, changing %zu of the %zu classes"), key,
              file.c_str(), counts.lines - counts.unmatched, counts.lines, changed,
              ids.size());
    if (counts.unmatched)
        G_warning(_("%s=%s: %zu of %zu lines named no class of SBRT <%s> and changed "
                    "nothing (the first names %s; its %zu classes have ids %d to %d)"),
                  key, file.c_str(), counts.unmatched, counts.lines, sbrt_name,
                  counts.first_unmatched.c_str(), ids.size(), ids.front(), ids.back());
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

void colors_from_rules(const RulesText &rules, const char *sbrt_name,
                       std::vector<sbrt::Material> &materials)
{
    CELL low, high;
    id_range(materials, low, high);
    // read and checked by the project's reader (never GRASS's, which ends
    // the process on a bad line and prints it): an error names the line's
    // number, never its content
    sbrt::ColorRules parsed;
    try {
        parsed = sbrt::parse_color_rules(rules.text, "rules=" + rules.file);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", sbrt::printable(e.what()).c_str());
    }
    GrassColors colors;
    set_grass_colors(parsed, low, high, colors.get());
    const size_t changed = take_colors(colors.get(), materials);
    std::vector<double> values;
    for (const sbrt::ColorRule &rule : parsed.rules)
        values.push_back(rule.value_in(low, high));
    const std::vector<int32_t> ids = class_ids(materials);
    report_counts("rules", rules.file, sbrt_name, count_color_rules(values, ids), changed,
                  ids);
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
            if (label && *label) // another user's map: any bytes (issue 48)
                materials[i].label = sbrt::valid_utf8(label);
        }
        Rast_free_cats(&cats);
    }
    if (have_colors < 0 && have_cats != 0)
        G_fatal_error(_("<%s> has neither a colour table nor categories"), name);
}

std::vector<sbrt::ClassStyle> parse_label_rules(const RulesText &rules)
{
    std::vector<sbrt::ClassStyle> parsed;
    try {
        std::istringstream in(rules.text);
        parsed = sbrt::parse_category_rules(in, "labels=" + rules.file);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", sbrt::printable(e.what()).c_str());
    }
    for (sbrt::ClassStyle &rule : parsed)
        rule.label = sbrt::valid_utf8(rule.label);
    return parsed;
}

void apply_label_rules(const std::vector<sbrt::ClassStyle> &label_rules, const char *file,
                       const char *sbrt_name, std::vector<sbrt::Material> &materials)
{
    const size_t changed = sbrt::apply_styles(materials, label_rules);
    const std::vector<int32_t> ids = class_ids(materials);
    report_counts("labels", file, sbrt_name, count_label_rules(label_rules, ids), changed,
                  ids);
}
