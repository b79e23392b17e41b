/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A view as a geologist asks for it (position and target, or
 *            azimuth, elevation and distance around the target) turned into
 *            a camera; the default distance frames the whole model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VIEW_HPP
#define SBRT_VIEW_HPP

#include <optional>
#include <vector>

#include "scene/camera.hpp"
#include "frame/coordinate_frame.hpp"
#include "model/model.hpp"

namespace sbrt {

/// Perspective, parallel (orthographic) or straight down over a 2D region.
enum class ViewKind { perspective, orthographic, top };

/// \brief A perspective or orthographic view; points in real map
/// coordinates (the tracer exaggerates them), angles in degrees.
struct View {
    ViewKind kind = ViewKind::perspective;
    std::optional<glm::dvec3> position, target; ///< target: the model's centre
    double azimuth = 225;   ///< where the camera looks from, clockwise from north
    double elevation = 30;  ///< above the horizon
    std::optional<double> distance; ///< from the target; none: framed
    double fov = 40;        ///< vertical field of view
    std::optional<double> ortho_height; ///< none: the model's diameter
};

/// Corners of the boxes over up to 8 x 8 blocks of the grid, each from the
/// model's bottom to the highest top in its block (exaggerated): a hull of
/// the model, tighter than its box where the terrain is not flat.
std::vector<glm::dvec3> framing_hull(const Model &model, const CoordinateFrame &frame);

/// Smallest distance along `offset` (unit, from `target` towards the
/// camera) at which `points` lie inside 95 % of an image of `aspect`
/// (width / height) with vertical field `fov`.
double framing_distance(const std::vector<glm::dvec3> &points, glm::dvec3 target,
                        glm::dvec3 offset, double fov, double aspect);

/// Where parallel rays towards `target`, coming from direction `offset`
/// (unit, from the target towards the camera), start: outside the model's
/// box whatever the target.
glm::dvec3 orthographic_start(const CoordinateFrame &frame, glm::dvec3 target,
                              glm::dvec3 offset);

/// The camera of `view` (not ViewKind::top) for a rows x cols image of
/// `model` drawn in `frame`. Unless position= is given, the model fills the
/// image: without target= the camera looks at the centre of the model's
/// image (not of its box), the distance (or an orthographic view's height)
/// makes the hull reach 95 % of the image on its tighter side.
Camera view_camera(const View &view, const Model &model, const CoordinateFrame &frame,
                   int rows, int cols);

} // namespace sbrt

#endif
