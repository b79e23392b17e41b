/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The camera of each frame: one view, an orbit, a flight along a
 *            vector line, keyframes, or the same view for a sweep
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_FRAME_CAMERAS_HPP
#define R3_SBRT_FRAME_CAMERAS_HPP

#include <vector>

#include "scene/camera.hpp"
#include "render_options.hpp"
#include "frame/coordinate_frame.hpp"

/// The cameras of frames 1..frames= of the request, framing `model` as read
/// in `frame` (the view does not move when strata are hidden).
std::vector<sbrt::Camera> frame_cameras(const RenderRequest &request,
                                        const sbrt::Model &model,
                                        const sbrt::CoordinateFrame &frame,
                                        const struct Cell_head &region);

#endif
