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

#include "camera.hpp"
#include "tracer.hpp"

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

/// Smallest distance along `offset` (unit, from `target` towards the
/// camera) at which the eight corners of the model's box lie inside 95 %
/// of an image of `aspect` (width / height) with vertical field `fov`.
double framing_distance(const Tracer &tracer, glm::dvec3 target, glm::dvec3 offset,
                        double fov, double aspect);

/// The camera of `view` (not ViewKind::top) for a rows x cols image.
Camera view_camera(const View &view, const Tracer &tracer, int rows, int cols);

} // namespace sbrt

#endif
