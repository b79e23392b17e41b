/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The outputs of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "outputs_part.hpp"

void OutputsPart::define(OptionTable &table)
{
    Option *output = table.add(G_define_standard_option(G_OPT_R_BASENAME_OUTPUT));
    output->required = NO;
    output->description =
        _("The image as the map <output> (its own colours) and <output>.red, "
          ".green, .blue (frames: <output>_NNNN...); none: png= only");
    output->guisection = _("Output");
    table.define_map_output("material",
                            _("Raster map of the class of the first opaque hit"));
    table.define_map_output("hit_elevation",
                            _("Raster map of the elevation (z) of the first hit"));
    table.define_map_output("depth",
                            _("Raster map of the distance from the camera to the hit"));
    table.define_standard(G_OPT_F_OUTPUT, "png", _("PNG file of the image too"),
                          _("Output"));
    table.define_flag('n',
                      _("No annotations in the PNG (legend, north arrow, vertical "
                        "exaggeration, scale bar)"),
                      _("Output"));
}

void OutputsPart::read(const Answers &a)
{
    output = a.text("output");
    material = a.text("material");
    hit_elevation = a.text("hit_elevation");
    depth = a.text("depth");
    png = a.text("png");
    annotate = !a.flag('n');
}
