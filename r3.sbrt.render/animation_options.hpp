/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The options of an animation
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_ANIMATION_OPTIONS_HPP
#define R3_SBRT_ANIMATION_OPTIONS_HPP

#include "render_options.hpp"

/// frames=, path=, angle=, path_map=, height=, keys=, range=, strds=,
/// video=, fps= (GUI section Animation).
void define_animation_options(RenderOptions &options);
/// Their answers into `request`, checked against the view (after it is read).
void read_animation_options(const RenderOptions &options, RenderRequest &request);

#endif
