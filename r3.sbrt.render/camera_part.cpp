/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The camera of a render request and its exaggeration
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "camera_part.hpp"

#include <cmath>
#include <sstream>

#include "request_error.hpp"

namespace {

void define_framing(OptionTable &table)
{
    Option *o = table.define("position", TYPE_DOUBLE,
                             _("Camera position (map units, unexaggerated)"), _("Camera"));
    o->key_desc = "x,y,z";
    o = table.define("target", TYPE_DOUBLE,
                     _("Point looked at (default: centre of the model)"), _("Camera"));
    o->key_desc = "x,y,z";
    o = table.define("azimuth", TYPE_DOUBLE,
                     _("Direction the camera looks from, degrees clockwise "
                       "from north (ignored with position=)"),
                     _("Camera"), "225");
    o->options = "0-360";
    o = table.define("elevation", TYPE_DOUBLE,
                     _("Camera angle above the horizon, degrees (ignored "
                       "with position=)"),
                     _("Camera"), "30");
    o->options = "-90-90";
    table.define("distance", TYPE_DOUBLE,
                 _("Distance from the target (default: frames the "
                   "model; ignored with position=)"),
                 _("Camera"));
    table.define("fov", TYPE_DOUBLE, _("Vertical field of view, degrees"), _("Camera"), "40");
    table.define("ortho_height", TYPE_DOUBLE,
                 _("Height of an orthographic view, map units "
                   "(default: frames the model)"),
                 _("Camera"));
}

} // namespace

void CameraPart::define(OptionTable &table)
{
    table.define_choice(
        "view", _("Projection of the view"), _("Camera"), "perspective",
        "perspective,orthographic,top",
        _("perspective;Perspective camera;"
          "orthographic;Parallel rays along target - position;"
          "top;Straight down, one pixel per cell of the current region "
          "(georeferenced outputs)"));
    Option *size = table.define("size", TYPE_INTEGER,
                                _("Image size in pixels (default: 640,480; view=top: the "
                                  "maps have the region's cells, the PNG enlarges them by "
                                  "whole pixels to fit this size, by default to 640 on "
                                  "its longer side)"),
                                _("Camera"));
    size->key_desc = "width,height";
    Option *tile = table.define("tile", TYPE_INTEGER,
                                _("Only this rectangle of the size= image: its first row and "
                                  "column (from 0, top left) and its rows and columns; tiles "
                                  "mosaic to the whole image exactly (r.patch)"),
                                _("Camera"));
    tile->key_desc = "row,col,rows,cols";
    define_framing(table);
}

void CameraPart::read_size(const Answers &a)
{
    if (a.given("size")) {
        const std::vector<double> size = a.numbers("size");
        if (size.size() != 2 || size[0] < 1 || size[1] < 1 ||
            size[0] != std::floor(size[0]) || size[1] != std::floor(size[1]) ||
            size[0] > 65536 || size[1] > 65536)
            bad_request(_("size= takes the image's width,height in pixels "
                          "(1 to 65536 each), e.g. size=1056,884"));
        width = int(size[0]);
        height = int(size[1]);
        size_given = true;
    }
    if (a.given("tile")) {
        const std::vector<double> t = a.numbers("tile");
        if (t.size() != 4 || t[0] < 0 || t[1] < 0 || t[2] < 1 || t[3] < 1 ||
            t[0] + t[2] > height || t[1] + t[3] > width)
            bad_request(_("tile= takes row,col,rows,cols of a rectangle within the "
                          "%d x %d image (size=), rows and columns from 0 at the "
                          "top left"),
                        width, height);
        if (view.kind == sbrt::ViewKind::top)
            bad_request(_("tile= is for perspective and orthographic views; a top "
                          "view's tile is a region (g.region)"));
        tile = {int(t[0]), int(t[1]), int(t[2]), int(t[3])};
    }
}

void CameraPart::read_view(const Answers &a)
{
    view.position = a.point("position");
    view.target = a.point("target");
    view.azimuth = a.number("azimuth");
    view.elevation = a.number("elevation");
    if (a.given("distance")) {
        view.distance = a.number("distance");
        if (!(*view.distance > 0))
            bad_request(_("distance= must be positive"));
    }
    view.fov = a.number("fov");
    if (!(view.fov > 0 && view.fov < 180))
        bad_request(_("fov=%g: the field of view must lie between 0 and "
                      "180 degrees"),
                    view.fov);
    if (a.given("ortho_height")) {
        view.ortho_height = a.number("ortho_height");
        if (!(*view.ortho_height > 0))
            bad_request(_("ortho_height= must be positive"));
    }
    if (view.position && view.target && *view.position == *view.target)
        bad_request(_("position= and target= are the same point: the "
                      "camera has no direction"));
}

void CameraPart::read(const Answers &a)
{
    const std::string kind = a.text("view");
    view.kind = kind == "top"            ? sbrt::ViewKind::top
                : kind == "orthographic" ? sbrt::ViewKind::orthographic
                                         : sbrt::ViewKind::perspective;
    read_size(a);
    read_view(a);
}

void ExaggerationPart::define(OptionTable &table)
{
    table.define("zexag", TYPE_DOUBLE,
                 _("Vertical exaggeration (about the model's bottom; default: "
                   "fitted to the model's extent and thickness)"),
                 _("Camera"));
}

void ExaggerationPart::read(const Answers &a)
{
    if (a.given("zexag")) {
        zexag = a.number("zexag");
        zexag_fitted = false;
        if (!(zexag > 0))
            bad_request(_("zexag=%g: the vertical exaggeration must be positive"), zexag);
    }
}

std::string ExaggerationPart::key() const
{
    std::ostringstream key;
    key << std::hexfloat << zexag;
    return key.str();
}
