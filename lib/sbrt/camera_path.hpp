/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sequences of views: a camera orbiting a vertical axis, and a
 *            clip plane sweeping across the model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CAMERA_PATH_HPP
#define SBRT_CAMERA_PATH_HPP

#include <vector>

#include "camera.hpp"
#include "scene.hpp"
#include "view.hpp"

namespace sbrt {

/// `p` turned by `degrees` about the vertical axis through `axis`,
/// counter-clockwise seen from above.
glm::dvec3 turn_about_vertical(glm::dvec3 p, glm::dvec3 axis, double degrees);

/// The cameras of an orbit of `frames` frames (rows x cols each): frame k
/// (from 1) is `view`'s camera turned by (k - 1) * angle / frames degrees
/// about the vertical axis through its target (target=, or the model's
/// centre). Unless position=, distance= or ortho_height= say otherwise,
/// every frame keeps the distance (or height) at which the model fits the
/// image in all of them: the model turns, it does not zoom.
std::vector<Camera> orbit_cameras(const View &view, const Tracer &tracer, int rows,
                                  int cols, int frames, double angle);

/// `plane` moved along its normal for frame k (from 1) of `frames`: frame
/// 1 cuts nothing of the model's box, each next frame cuts a further
/// 1 / frames of its extent along the normal (the removed side is the one
/// the normal points to).
ClipPlane swept_plane(const ClipPlane &plane, const Tracer &tracer, int frame,
                      int frames);

} // namespace sbrt

#endif
