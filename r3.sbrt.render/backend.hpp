/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Traces the image's first hits with the backend the request
 *            names: OpenGL through EGL or OSMesa, or the CPU ray caster
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BACKEND_HPP
#define R3_SBRT_BACKEND_HPP

#include "render_options.hpp"
#include "hit_image.hpp"

/// backend=egl|osmesa fail with the reason; backend=auto takes a hardware
/// GL context where one works and the CPU otherwise (a software OpenGL is
/// slower than the CPU ray caster on the same cores).
sbrt::HitImage trace_hits(const RenderRequest &request, const sbrt::Tracer &tracer,
                          const sbrt::Camera &camera);

#endif
