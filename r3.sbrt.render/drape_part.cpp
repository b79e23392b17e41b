/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The drape of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "drape_part.hpp"

#include <sstream>

#include "input_part.hpp"
#include "request_error.hpp"

void DrapePart::define(OptionTable &table)
{
    Option *o = table.define_standard(
        G_OPT_R_INPUTS, "texture",
        _("One map with a colour table, or three maps red,green,blue (0-255)"), _("Drape"));
    o->label = _("Raster map(s) draped on the terrain surface");
    o = table.define("texture_blend", TYPE_DOUBLE,
                     _("Share of the texture in the surface colour "
                       "(0: class colours, 1: texture only)"),
                     _("Drape"), "1");
    o->options = "0-1";
}

void DrapePart::read(const Answers &a)
{
    texture = a.parts("texture");
    for (const std::string &map : texture)
        check_map_name("texture", map);
    if (texture.size() != 0 && texture.size() != 1 && texture.size() != 3)
        bad_request(_("texture= takes one map (with its colour table) or three "
                      "maps red,green,blue, not %zu"),
                    texture.size());
    texture_blend = a.number("texture_blend");
    if (!(texture_blend >= 0 && texture_blend <= 1))
        bad_request(_("texture_blend=%g must lie in 0..1"), texture_blend);
}

std::string DrapePart::key() const
{
    std::ostringstream key;
    key << std::hexfloat << texture_blend;
    for (const std::string &map : texture)
        key << ',' << map;
    return key.str();
}
