/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Material colours from colour tables
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "material_colors.hpp"
#include "request_error.hpp"
#include "grass_color_rules.hpp"

#include <algorithm>

void apply_color_option(const RenderRequest &request, std::vector<sbrt::Material> &materials)
{
    if (request.color.empty() && request.rules.empty())
        return;
    if (materials.size() < 2)
        return;
    CELL low = materials[1].id, high = materials[1].id;
    for (size_t i = 1; i < materials.size(); ++i) {
        low = std::min(low, materials[i].id);
        high = std::max(high, materials[i].id);
    }
    GrassColors table;
    struct Colors &colors = *table.get();
    if (!request.color.empty())
        Rast_make_colors(&colors, request.color.c_str(), low, high); // fatal if unknown
    else {
        // read and checked by us: GRASS's reader would end the view server
        // on a bad line and print the line (of whatever file it was given)
        const sbrt::ColorRules rules =
            request.rules == "-"
                ? sbrt::read_color_rules_stream(stdin, "rules=- (standard input)")
                : sbrt::read_color_rules_file(request.rules, "rules=" + request.rules);
        set_grass_colors(rules, low, high, &colors);
    }
    for (size_t i = 1; i < materials.size(); ++i) {
        int red, green, blue;
        CELL id = materials[i].id;
        if (!Rast_get_c_color(&id, &red, &green, &blue, &colors))
            continue; // no rule for this class: keep its colour
        materials[i].red = uint8_t(red);
        materials[i].green = uint8_t(green);
        materials[i].blue = uint8_t(blue);
        materials[i].has_color = true;
    }
}
