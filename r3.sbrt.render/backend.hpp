/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Backend choice, and the render on it with its timing messages
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BACKEND_HPP
#define R3_SBRT_BACKEND_HPP

#include <memory>

#include "gl_context.hpp"
#include "render_options.hpp"
#include "renderer.hpp"

/// The GL context to render in, or none for the CPU. backend=egl|osmesa
/// fail with the reason; backend=auto takes a hardware GL context where
/// one works and the CPU otherwise (a software OpenGL is slower than the
/// CPU ray caster on the same cores); boreholes and fences (`overlays`)
/// are drawn by the CPU ray caster only.
std::unique_ptr<sbrt_gl::GlContext> choose_gl_context(const RenderRequest &request,
                                                      bool overlays);

/// Renders `camera` into `sink`, on the GPU of `context` where there is
/// one (and the model fits it: else, with backend=auto, on the CPU).
void render_on_backend(const RenderRequest &request, const sbrt::Renderer &renderer,
                       const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                       const sbrt::BandSink &sink, sbrt_gl::GlContext *context);

#endif
