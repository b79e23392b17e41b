/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The options of an animation: frames, path, range, tile of a
 *            job, the dataset and the video of the sequence
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "animation_options.hpp"

#include <cstdio>
#include <cstdlib>

#include "option_parts.hpp"
#include "request_error.hpp"

using namespace option_parts;

void define_animation_options(RenderOptions &options)
{
    RenderOptions *o = &options;
    o->frames = define("frames", TYPE_INTEGER,
                       _("Number of frames: an animation along path= (maps and "
                         "PNG files get the frame number, _0001 ...)"),
                       _("Animation"), "1");
    o->path = define_choice(
        "path", _("How the frames move"), _("Animation"), "orbit",
        "orbit,line,keys,sweep",
        _("orbit;The camera turns about the vertical axis through the target, "
          "counter-clockwise seen from above, by angle= over the frames;"
          "line;The camera moves along the line of path_map=, evenly by "
          "length, looking ahead (or at target=);"
          "keys;The camera moves through the keyframes of keys=, smoothly;"
          "sweep;The clip plane (plane=, or section=) moves along its normal "
          "across the model, the camera stays"));
    o->angle = define("angle", TYPE_DOUBLE,
                      _("Arc of an orbit, degrees (360: a full turn)"),
                      _("Animation"), "360");
    o->path_map = define_standard(G_OPT_V_INPUT, "path_map",
                                  _("Vector line map the camera flies along "
                                    "(path=line; the first line)"),
                                  _("Animation"));
    o->height = define("height", TYPE_DOUBLE,
                       _("path=line: the camera this high above the model's top "
                         "(default: the line's own z)"),
                       _("Animation"));
    o->keys = define_standard(G_OPT_F_INPUT, "keys",
                              _("path=keys: lines of x y z tx ty tz [fov] (camera "
                                "position, target, field of view)"),
                              _("Animation"));
    o->range = define("range", TYPE_STRING,
                      _("Only these frames (first-last), as in the full run: "
                        "for jobs in parallel"),
                      _("Animation"));
    o->range->key_desc = "first-last";
    o->strds = define_standard(G_OPT_STRDS_OUTPUT, "strds",
                               _("Space-time raster dataset (relative time) of "
                                 "the frames' <output>_NNNN maps, for "
                                 "g.gui.animation"),
                               _("Animation"));
    o->video = define_standard(G_OPT_F_OUTPUT, "video",
                               _("Video file of the frames (.mp4, .webm or .gif; "
                                 "needs ffmpeg)"),
                               _("Animation"));
    o->fps = define("fps", TYPE_DOUBLE, _("Frames per second of video="),
                    _("Animation"), "12");
}

void read_animation_options(const RenderOptions &o, RenderRequest &r)
{
    r.frames = std::atoi(o.frames->answer);
    if (r.frames < 1)
        bad_request(_("frames=%s: give the number of frames, 1 or more"),
                      o.frames->answer);
    r.path = sbrt::parse_path_kind(o.path->answer);
    r.angle = read_double(o.angle);
    r.path_map = answer_or(o.path_map);
    r.keys = answer_or(o.keys);
    if (o.height->answer)
        r.line_height = read_double(o.height);
    if (r.path == sbrt::PathKind::line && r.path_map.empty())
        bad_request(_("path=line flies along a vector line: give path_map="));
    if (r.path == sbrt::PathKind::keys && r.keys.empty())
        bad_request(_("path=keys moves through keyframes: give keys= (a file)"));
    if ((r.path == sbrt::PathKind::line || r.path == sbrt::PathKind::keys) && r.view.kind == sbrt::ViewKind::top)
        bad_request(_("path=%s moves the camera; a top view does not move "
                        "(view=perspective or orthographic)"),
                      sbrt::path_kind_name(r.path));
    r.first_frame = 1;
    r.last_frame = r.frames;
    if (o.range->answer) {
        int first = 0, last = 0;
        char end = 0;
        const int n = std::sscanf(o.range->answer, "%d-%d%c", &first, &last, &end);
        if (n == 1 && std::sscanf(o.range->answer, "%d%c", &first, &end) == 1)
            last = first;
        else if (n != 2)
            first = 0;
        if (first < 1 || last < first || last > r.frames)
            bad_request(_("range=%s: give first-last with 1 <= first <= last <= "
                            "frames (%d)"),
                          o.range->answer, r.frames);
        r.first_frame = first;
        r.last_frame = last;
    }
    r.strds = answer_or(o.strds);
    r.video = answer_or(o.video);
    r.fps = read_double(o.fps);
    if (!(r.fps > 0))
        bad_request(_("fps= must be positive"));
    r.overwrite = G_check_overwrite(0, nullptr);
    if (r.frames == 1 && (!r.strds.empty() || !r.video.empty()))
        bad_request(_("strds= and video= make a sequence: give frames= (2 or more)"));
    if (r.frames > 1 && r.path == sbrt::PathKind::orbit && r.view.kind == sbrt::ViewKind::top)
        bad_request(_("path=orbit turns the camera; a top view does not turn "
                        "(view=perspective or orthographic)"));
    if (r.frames > 1 && r.path == sbrt::PathKind::sweep && r.planes.empty() && !r.section)
        bad_request(_("path=sweep moves a clip plane: give plane= or section="));
}
