/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   What a Renderer is built from: the model after hide=, the
 *            scene (planes, boreholes, fence, translucency) and the shading
 *            of a request. One preparation for the module's frames and for
 *            the view server's (g.gui.sbrt), so both draw the same image.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PREPARED_SCENE_HPP
#define R3_SBRT_PREPARED_SCENE_HPP

#include "scene/camera.hpp"
#include "shading/drape.hpp"
#include "shading/property_paint.hpp"
#include "model/model.hpp"
#include "render_options.hpp"
#include "scene/scene.hpp"
#include "shading/shading.hpp"

/// \brief The model to draw (strata of hide= removed, or marked hidden in
/// the scene) and its scene.
struct PreparedScene {
    sbrt::Model model;
    sbrt::Scene scene;
};

/// Hides the strata of hide= of `model` (as read, colours applied) and
/// builds the scene of the request; sections and split logs face `camera`.
/// The strata are crossed as air while tracing (the model stays as read),
/// or, where boreholes or a fence read the stacks themselves, removed from
/// the model.
PreparedScene prepare_scene(const RenderRequest &request, sbrt::Model model,
                            const sbrt::Camera &camera);

/// The shading of the request; `drape` (or null) outlives it.
/// `property` (or null) too.
sbrt::Shading make_shading(const RenderRequest &request, const sbrt::Drape *drape,
                           const sbrt::PropertyPaint *property = nullptr,
                           const sbrt::UncertaintyFade *fade = nullptr);

#endif
