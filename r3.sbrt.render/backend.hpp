/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Backend choice, and the render on it with its timing messages
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_BACKEND_HPP
#define R3_SBRT_BACKEND_HPP

#include <memory>
#include <optional>

#include "gl_context.hpp"
#include "gpu_renderer.hpp"
#include "render_options.hpp"
#include "renderer.hpp"

/// The GL context to render in, or none for the CPU. backend=egl|osmesa
/// fail with the reason; backend=auto takes a hardware GL context where
/// one works and the CPU otherwise (a software OpenGL is slower than the
/// CPU ray caster on the same cores). Boreholes alone and fence diagrams
/// are traced and shaded on the GPU; boreholes drawn with the model go to
/// the GPU with the model, their pixels traced on the CPU.
std::unique_ptr<sbrt_gl::GlContext> choose_gl_context(const RenderRequest &request);

/// \brief Where the frames of one prepared scene render: the CPU, or the
/// GPU of a context, the model uploaded once (at the first frame) and kept
/// for the next ones; with backend=auto the CPU where the GPU cannot hold
/// the model.
class Backend {
public:
    /// `kept_atlas`: where a paged model's blocks on the GPU are kept
    /// between scenes (GpuOptions::kept_atlas), or null.
    Backend(const RenderRequest &request, const sbrt::Renderer &renderer,
            sbrt_gl::GlContext *context,
            std::shared_ptr<sbrt_gl::GpuPageAtlas> *kept_atlas = nullptr);
    Backend(const Backend &) = delete;
    Backend &operator=(const Backend &) = delete;

    /// Renders `camera` into `sink`.
    void render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                const sbrt::BandSink &sink);

private:
    const RenderRequest &request_;
    const sbrt::Renderer &renderer_;
    sbrt_gl::GlContext *context_;
    std::shared_ptr<sbrt_gl::GpuPageAtlas> *kept_atlas_;
    bool tried_gpu_ = false;
    int frames_ = 0; ///< rendered on the GPU
    std::optional<sbrt_gl::GpuRenderer> gpu_; ///< the scene, its model on the GPU
};

#endif
