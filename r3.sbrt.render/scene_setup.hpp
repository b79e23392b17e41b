/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The scene's visual operations from the request: hidden
 *            and translucent classes (ids, aliases or labels) and clip planes
 *            (SectionsPart::clip_planes)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SCENE_SETUP_HPP
#define R3_SBRT_SCENE_SETUP_HPP

#include <vector>

#include "scene/camera.hpp"
#include "render_options.hpp"
#include "scene/scene.hpp"

/// Material indices of hide= (class ids, aliases or labels:
/// sbrt::ClassNames); an error names an unknown class and lists the names
/// of every class by id.
std::vector<uint32_t> hidden_materials(const RenderRequest &request,
                                       const sbrt::Model &model);

/// opacity= as extinctions (alpha over opacity_length=, default one
/// cell) and the materials' colours; empty without opacity=.
sbrt::Translucency translucency(const RenderRequest &request,
                                const sbrt::Model &model);

#endif
