/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Hidden and translucent classes, clip planes
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene_setup.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "model/class_names.hpp"
#include "scene/scene_parts.hpp"

namespace {

/// "SBRT <input>", as the module names the model in its messages.
std::string model_name(const RenderRequest &request)
{
    return "SBRT <" + request.input + ">";
}

} // namespace

std::vector<uint32_t> hidden_materials(const RenderRequest &request,
                                       const sbrt::Model &model)
{
    if (request.hide.empty())
        return {};
    return sbrt::ClassNames(model.materials()).resolve(request.hide, "hide",
                                                       model_name(request));
}

sbrt::Translucency translucency(const RenderRequest &request,
                                const sbrt::Model &model)
{
    if (request.opacity.empty())
        return {};
    const sbrt::Frame &f = model.frame();
    const sbrt::ClassNames names(model.materials());
    std::vector<std::pair<uint32_t, double>> alphas;
    for (const auto &[name, alpha] : request.opacity)
        alphas.emplace_back(names.resolve_one(name, "opacity", model_name(request)), alpha);
    return sbrt::make_translucency(
        model, alphas, request.opacity_length.value_or(std::sqrt(f.ew_res() * f.ns_res())));
}
