/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The shading of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading_part.hpp"

#include <cstdlib>

#include "request_error.hpp"

void ShadingPart::define(OptionTable &table)
{
    Option *o = table.define("light", TYPE_DOUBLE,
                             _("Light direction: azimuth,elevation in degrees"),
                             _("Shading"), "315,45");
    o->key_desc = "azimuth,elevation";
    o = table.define("ambient", TYPE_DOUBLE, _("Ambient light share (0-1)"), _("Shading"),
                     "0.35");
    o->options = "0-1";
    o = table.add(G_define_standard_option(G_OPT_C));
    o->key = "background";
    o->answer = const_cast<char *>("white");
    o->description = _("Colour where rays miss the model");
    o->guisection = _("Shading");
    table.define_choice(
        "normals", _("Surface normals for lighting"), _("Shading"), "face", "face,kernel",
        _("face;Exact normal of the cell wall, top or bottom that was hit;"
          "kernel;Image-space k x k x k kernel over the depth image "
          "(smoother, as in Graciano et al. 2018)"));
    o = table.define("kernel", TYPE_INTEGER, _("Kernel size k of normals=kernel (odd)"),
                     _("Shading"), "5");
    o->options = "3-11";
    table.define("smooth", TYPE_DOUBLE,
                 _("Gaussian smoothing of the normals, sigma in pixels "
                   "(0: none)"),
                 _("Shading"), "0");
}

namespace {

/// Longest colour text handed to G_str_to_color (its buffer: 100 bytes).
constexpr size_t MAX_COLOUR_TEXT = 64;

} // namespace

void ShadingPart::read(const Answers &a)
{
    const std::vector<double> light = a.numbers("light");
    if (light.size() != 2)
        bad_request(_("light= needs azimuth,elevation"));
    light_azimuth = light[0];
    light_elevation = light[1];
    ambient = a.number("ambient");
    int red, green, blue;
    const std::string colour = a.text("background");
    // GRASS 8.2's G_str_to_color copies the text into a buffer of 100
    // bytes: a longer one (no colour is) overflows it
    if (colour.size() >= MAX_COLOUR_TEXT ||
        G_str_to_color(colour.c_str(), &red, &green, &blue) != 1)
        bad_request(_("background=<%s> is not a colour"), shortened(colour, 100).c_str());
    background = {uint8_t(red), uint8_t(green), uint8_t(blue)};
    normals = a.text("normals") == "kernel" ? sbrt::Normals::kernel : sbrt::Normals::face;
    kernel = std::atoi(a.text("kernel").c_str());
    if (kernel % 2 == 0)
        bad_request(_("kernel=%d: the kernel size must be odd (3, 5, 7, 9 "
                      "or 11)"),
                    kernel);
    smooth = a.number("smooth");
    if (smooth < 0)
        bad_request(_("smooth=%g must not be negative"), smooth);
}

void ShadingPart::check(const CameraPart &camera) const
{
    if (camera.tile && normals == sbrt::Normals::kernel)
        bad_request(_("tile= with normals=kernel: the kernel reads pixels across "
                      "the tile's edges, so tiles would not mosaic exactly; use "
                      "normals=face"));
}
