/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The model after hide=, the scene and the shading of a request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "prepared_scene.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "borehole_setup.hpp"
#include "scene/hidden_materials.hpp"
#include "scene_setup.hpp"
#include "skipping_report.hpp"
#include "vector_input.hpp"

PreparedScene prepare_scene(const RenderRequest &request, sbrt::Model model,
                            const sbrt::Camera &camera)
{
    const std::vector<uint32_t> hidden = hidden_materials(request, model);
    const bool while_tracing = request.boreholes.empty() && request.fence.empty();
    // the boreholes need the model as read where strata are hidden
    const sbrt::Model original = hidden.empty() || request.boreholes.empty()
                                     ? sbrt::Model()
                                     : model;
    std::vector<uint8_t> hidden_mask;
    if (!hidden.empty() && while_tracing) {
        hidden_mask.assign(model.materials().size(), 0);
        for (const uint32_t m : hidden)
            hidden_mask[m] = 1;
        report_hidden_while_tracing(hidden.size());
    }
    else if (!hidden.empty()) {
        sbrt::Model left = sbrt::hide_materials(model, hidden);
        report_hidden(model, left, hidden.size());
        model = std::move(left);
    }
    PreparedScene prepared{std::move(model), {}};
    sbrt::Scene &scene = prepared.scene;
    scene.hidden = std::move(hidden_mask);
    scene.planes = request.clip_planes(camera);
    if (!request.boreholes.empty()) {
        scene.boreholes = make_boreholes(request, hidden.empty() ? prepared.model : original,
                                         prepared.model, hidden);
        const sbrt::Frame &f = prepared.model.frame();
        scene.borehole_radius =
            request.borehole_radius.value_or(0.4 * std::min(f.ew_res(), f.ns_res()));
        if (request.split_logs) {
            // the log on the left half as the camera sees it
            const glm::dvec2 right(camera.du());
            scene.split = -glm::normalize(right);
        }
        report_borehole_bytes(prepared.model, scene.boreholes, request.boreholes_only);
    }
    if (!request.fence.empty())
        scene.fence = read_fence(request.fence);
    scene.draw_model = !request.boreholes_only && request.fence.empty();
    scene.skip_empty_space = !request.walk_every_cell;
    // after the boreholes: a log may have added classes
    scene.translucency = translucency(request, prepared.model);
    return prepared;
}

sbrt::Shading make_shading(const RenderRequest &request, const sbrt::Drape *drape,
                           const sbrt::PropertyPaint *property,
                           const sbrt::UncertaintyFade *fade)
{
    sbrt::Shading shading;
    // a top view is a map: lit from straight above, its flat tops in the
    // legend's colours (issue 51, item 4)
    shading.light = sbrt::Shading::light_of_view(request.view.kind, request.light_azimuth,
                                                 request.light_elevation);
    shading.ambient = request.ambient;
    shading.background = request.background;
    shading.normals = request.normals;
    shading.kernel = request.kernel;
    shading.smooth = request.smooth;
    shading.drape = drape;
    shading.property = property;
    shading.fade = fade;
    return shading;
}
