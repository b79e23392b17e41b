/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The animation of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "animation_part.hpp"

#include <cstdio>
#include <cstdlib>

#include "input_part.hpp"
#include "request_error.hpp"

namespace {

void define_outputs(OptionTable &table)
{
    Option *o = table.define("range", TYPE_STRING,
                             _("Only these frames (first-last), as in the full run: "
                               "for jobs in parallel"),
                             _("Animation"));
    o->key_desc = "first-last";
    table.define_standard(G_OPT_STRDS_OUTPUT, "strds",
                          _("Space-time raster dataset (relative time) of "
                            "the frames' <output>_NNNN maps, for "
                            "g.gui.animation"),
                          _("Animation"));
    table.define_standard(G_OPT_F_OUTPUT, "video",
                          _("Video file of the frames (.mp4, .webm or .gif; "
                            "needs ffmpeg)"),
                          _("Animation"));
    table.define("fps", TYPE_DOUBLE, _("Frames per second of video="), _("Animation"), "12");
}

} // namespace

void AnimationPart::define(OptionTable &table)
{
    table.define("frames", TYPE_INTEGER,
                 _("Number of frames: an animation along path= (maps and "
                   "PNG files get the frame number, _0001 ...)"),
                 _("Animation"), "1");
    table.define_choice(
        "path", _("How the frames move"), _("Animation"), "orbit", "orbit,line,keys,sweep",
        _("orbit;The camera turns about the vertical axis through the target, "
          "counter-clockwise seen from above, by angle= over the frames;"
          "line;The camera moves along the line of path_map=, evenly by "
          "length, looking ahead (or at target=);"
          "keys;The camera moves through the keyframes of keys=, smoothly;"
          "sweep;The clip plane (plane=, or section=) moves along its normal "
          "across the model, the camera stays"));
    table.define("angle", TYPE_DOUBLE, _("Arc of an orbit, degrees (360: a full turn)"),
                 _("Animation"), "360");
    table.define_standard(G_OPT_V_INPUT, "path_map",
                          _("Vector line map the camera flies along "
                            "(path=line; the first line)"),
                          _("Animation"));
    table.define("height", TYPE_DOUBLE,
                 _("path=line: the camera this high above the model's top "
                   "(default: the line's own z)"),
                 _("Animation"));
    table.define_standard(G_OPT_F_INPUT, "keys",
                          _("path=keys: lines of x y z tx ty tz [fov] (camera "
                            "position, target, field of view)"),
                          _("Animation"));
    define_outputs(table);
}

void AnimationPart::read_range(const Answers &a)
{
    first_frame = 1;
    last_frame = frames;
    if (!a.given("range"))
        return;
    const std::string range = a.text("range");
    int first = 0, last = 0;
    char end = 0;
    const int n = std::sscanf(range.c_str(), "%d-%d%c", &first, &last, &end);
    if (n == 1 && std::sscanf(range.c_str(), "%d%c", &first, &end) == 1)
        last = first;
    else if (n != 2)
        first = 0;
    if (first < 1 || last < first || last > frames)
        bad_request(_("range=%s: give first-last with 1 <= first <= last <= "
                      "frames (%d)"),
                    shortened(range, 100).c_str(), frames);
    first_frame = first;
    last_frame = last;
}

void AnimationPart::read(const Answers &a)
{
    frames = std::atoi(a.text("frames", "1").c_str());
    if (frames < 1)
        bad_request(_("frames=%s: give the number of frames, 1 or more"),
                    shortened(a.text("frames"), 100).c_str());
    path = sbrt::parse_path_kind(a.text("path", "orbit"));
    angle = a.number("angle");
    path_map = a.text("path_map");
    check_map_name("path_map", path_map);
    keys = a.text("keys");
    if (a.given("height"))
        line_height = a.number("height");
    if (path == sbrt::PathKind::line && path_map.empty())
        bad_request(_("path=line flies along a vector line: give path_map="));
    if (path == sbrt::PathKind::keys && keys.empty())
        bad_request(_("path=keys moves through keyframes: give keys= (a file)"));
    read_range(a);
    strds = a.text("strds");
    video = a.text("video");
    fps = a.number("fps");
    if (!(fps > 0))
        bad_request(_("fps= must be positive"));
    overwrite = G_check_overwrite(0, nullptr);
    if (frames == 1 && (!strds.empty() || !video.empty()))
        bad_request(_("strds= and video= make a sequence: give frames= (2 or more)"));
}

void AnimationPart::check(const CameraPart &camera, const SectionsPart &sections) const
{
    const bool top = camera.view.kind == sbrt::ViewKind::top;
    if ((path == sbrt::PathKind::line || path == sbrt::PathKind::keys) && top)
        bad_request(_("path=%s moves the camera; a top view does not move "
                      "(view=perspective or orthographic)"),
                    sbrt::path_kind_name(path));
    if (frames > 1 && path == sbrt::PathKind::orbit && top)
        bad_request(_("path=orbit turns the camera; a top view does not turn "
                      "(view=perspective or orthographic)"));
    if (frames > 1 && path == sbrt::PathKind::sweep && sections.planes.empty() &&
        !sections.section)
        bad_request(_("path=sweep moves a clip plane: give plane= or section="));
}
