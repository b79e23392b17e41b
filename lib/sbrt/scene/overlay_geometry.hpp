/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Exact 2D ray geometry of the vertical overlays: a ray against
 *            a borehole's infinite vertical cylinder and against a fence
 *            curtain (a vertical plane above a segment), and the grid cells
 *            each overlay may touch
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_OVERLAY_GEOMETRY_HPP
#define SBRT_OVERLAY_GEOMETRY_HPP

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "model/model.hpp"
#include "scene/scene.hpp"

namespace sbrt {

/// The parameters t0 <= t1 where the horizontal projection o + t d of a ray
/// is at distance r from c; false where it never is (or d is vertical and
/// o lies outside, where [t0, t1] would be unbounded: then t0 = -inf and
/// t1 = +inf when o lies inside).
bool ray_cylinder(glm::dvec2 o, glm::dvec2 d, glm::dvec2 c, double r,
                  double &t0, double &t1);

/// The parameter t where o + t d crosses the panel's segment; false where
/// it runs parallel to it or misses it. `normal` is the panel's unit
/// normal turned towards the ray's origin.
bool ray_panel(glm::dvec2 o, glm::dvec2 d, const FencePanel &panel, double &t,
               glm::dvec2 &normal);

/// Cells (row-major index, row 0 north) of `frame` within `margin` map
/// units of the segment a-b (a point when a == b), each once.
std::vector<uint64_t> cells_near_segment(const Frame &frame, glm::dvec2 a,
                                         glm::dvec2 b, double margin);

} // namespace sbrt

#endif
