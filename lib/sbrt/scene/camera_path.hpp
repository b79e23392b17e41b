/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sequences of views: a camera orbiting a vertical axis, and a
 *            clip plane sweeping across the model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CAMERA_PATH_HPP
#define SBRT_CAMERA_PATH_HPP

#include <string>
#include <vector>

#include "scene/camera.hpp"
#include "scene/scene.hpp"
#include "scene/view.hpp"

namespace sbrt {

/// \brief How the frames of an animation move: turning about a vertical
/// axis, along a line, through keyframes, or the plane sweeping across.
enum class PathKind { orbit, line, keys, sweep };

/// The kind a word names ("orbit", "line", "keys", "sweep"); sbrt::Error
/// listing them for any other word.
PathKind parse_path_kind(const std::string &word);
const char *path_kind_name(PathKind kind);

/// `p` turned by `degrees` about the vertical axis through `axis`,
/// counter-clockwise seen from above.
glm::dvec3 turn_about_vertical(glm::dvec3 p, glm::dvec3 axis, double degrees);

/// The cameras of an orbit of `frames` frames (rows x cols each): frame k
/// (from 1) is `view`'s camera turned by (k - 1) * angle / frames degrees
/// about the vertical axis through its target (target=, or the model's
/// centre). Unless position=, distance= or ortho_height= say otherwise,
/// every frame keeps the distance (or height) at which the model fits the
/// image in all of them: the model turns, it does not zoom.
std::vector<Camera> orbit_cameras(const View &view, const Model &model,
                                  const CoordinateFrame &frame, int rows,
                                  int cols, int frames, double angle);

/// \brief A keyframe of path=keys: camera position, target, vertical field
/// of view (real map coordinates, degrees).
struct Keyframe {
    glm::dvec3 position, target;
    double fov = 40;
};

/// Keyframes from text: one a line, "x y z tx ty tz [fov]" (blanks or
/// commas between; # starts a comment); `fov` where a line has none.
/// Throws sbrt::Error naming the line that is wrong, or with fewer than two.
std::vector<Keyframe> parse_keyframes(const std::string &text, double fov);

/// Frame k (from 1) of `frames` through the keyframes, evenly in their
/// index (frame 1 at the first key, the last frame at the last): position
/// and target on Catmull-Rom splines through the keys, fov linear.
Keyframe keyframe_at(const std::vector<Keyframe> &keys, int frame, int frames);

/// Horizontal length of a polyline (map units).
double line_length(const std::vector<glm::dvec3> &line);

/// Frame k (from 1) of `frames` along a polyline (map coordinates with z),
/// evenly spaced by length, the first frame at its start and the last at
/// its end: the point, and the direction it moves in there (unit, from
/// the segment's direction; horizontal where it has no length).
void along_line(const std::vector<glm::dvec3> &line, int frame, int frames,
                glm::dvec3 &point, glm::dvec3 &direction);

/// The elevation (real map units) of the model's top at (x, y): the top of
/// the highest interval of that cell's stack; outside the grid or over an
/// empty column, the top of the whole model.
double surface_elevation(const Model &model, const CoordinateFrame &frame, double x,
                         double y);

/// `plane` moved along its normal for frame k (from 1) of `frames`: frame
/// 1 cuts nothing of the model's box, each next frame cuts a further
/// 1 / frames of its extent along the normal (the removed side is the one
/// the normal points to).
ClipPlane swept_plane(const ClipPlane &plane, const CoordinateFrame &box, int frame,
                      int frames);

} // namespace sbrt

#endif
