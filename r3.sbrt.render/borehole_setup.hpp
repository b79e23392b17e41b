/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Boreholes of the scene from boreholes=: the model's stack
 *            under each point, or its logged intervals as a stack
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BOREHOLE_SETUP_HPP
#define R3_SBRT_BOREHOLE_SETUP_HPP

#include <vector>

#include "render_options.hpp"
#include "scene/scene_parts.hpp"
#include "scene/scene.hpp"

/// The boreholes of the request. `shown` is the model drawn (strata of
/// `hidden` already removed): a log's classes missing from it are added
/// to its materials; `original` is the model as read (its surface is the
/// reference of depths for 2D points). With -b hide= applies to the
/// cylinders; without, they show every class, so that they stand out of
/// a model whose upper strata are hidden. Points outside the model are
/// skipped with a warning.
std::vector<sbrt::Borehole> make_boreholes(const RenderRequest &request,
                                           const sbrt::Model &original,
                                           sbrt::Model &shown,
                                           const std::vector<uint32_t> &hidden);

/// Verbose message: the bytes the boreholes' stacks take against the
/// model's (with -b, all the tracer reads).
void report_borehole_bytes(const sbrt::Model &model,
                           const std::vector<sbrt::Borehole> &boreholes,
                           bool only);


#endif
