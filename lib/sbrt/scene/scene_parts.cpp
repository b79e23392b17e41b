/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sections, translucent strata and borehole logs of a scene
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/scene_parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "model/material_table.hpp"
#include "util/error.hpp"

namespace sbrt {

LogReference parse_log_reference(const std::string &word)
{
    if (word == log_reference_name(LogReference::elevation))
        return LogReference::elevation;
    if (word == log_reference_name(LogReference::depth))
        return LogReference::depth;
    fail("log reference: '", word, "' is neither elevation nor depth");
}

const char *log_reference_name(LogReference reference)
{
    return reference == LogReference::depth ? "depth" : "elevation";
}

ClipPlane section_plane(glm::dvec2 a, glm::dvec2 b, const Camera &camera)
{
    if (a == b)
        fail("section: its two points are the same (", a.x, ", ", a.y, ")");
    const glm::dvec3 point(a.x, a.y, 0);
    // horizontal normal to the left of a -> b
    glm::dvec3 normal(-(b.y - a.y), b.x - a.x, 0);
    // towards the camera: the side the camera is on is removed
    const double facing = camera.parallel() ? glm::dot(normal, -camera.forward())
                                            : glm::dot(normal, camera.origin() - point);
    if (facing < 0)
        normal = -normal;
    return {point, normal};
}

Translucency make_translucency(const Model &model,
                               const std::vector<std::pair<uint32_t, double>> &alphas,
                               double length)
{
    Translucency tr;
    if (alphas.empty())
        return tr;
    if (!(length > 0))
        fail("translucency: the length alpha applies over must be positive (", length, ")");
    tr.length = length;
    const size_t count = model.materials().size();
    tr.extinction.assign(count, std::numeric_limits<double>::infinity());
    tr.color.assign(count, glm::dvec3(0));
    for (uint32_t m = 1; m < count; ++m) {
        const auto rgb = material_color(model, m);
        tr.color[m] = glm::dvec3(rgb[0], rgb[1], rgb[2]) / 255.0;
    }
    for (const auto &[material, alpha] : alphas) {
        if (material == EMPTY || material >= count)
            fail("translucency: no material ", material);
        tr.extinction[material] = extinction_of(alpha, length);
    }
    return tr;
}

std::vector<Interval> log_stack(const Frame &frame, std::vector<LoggedInterval> logged,
                                const std::vector<uint32_t> &hidden)
{
    std::sort(logged.begin(), logged.end(),
              [](const LoggedInterval &a, const LoggedInterval &b) {
                  return a.bottom < b.bottom;
              });
    std::vector<Interval> stack;
    auto push = [&](uint32_t material, float top) {
        if (!stack.empty() && stack.back().material == material)
            stack.back().top = top;
        else
            stack.push_back({material, top});
    };
    float reached = 0; // local z the stack covers so far
    for (const LoggedInterval &iv : logged) {
        const float bottom = float(std::max(0.0, frame.local_z(iv.bottom)));
        const float top = float(frame.local_z(iv.top));
        if (!(top > reached))
            continue; // below the model or inside an interval below
        if (bottom > reached)
            push(EMPTY, bottom);
        const bool is_hidden =
            std::find(hidden.begin(), hidden.end(), iv.material) != hidden.end();
        push(is_hidden ? EMPTY : iv.material, top);
        reached = top;
    }
    while (!stack.empty() && stack.back().material == EMPTY)
        stack.pop_back();
    return stack;
}

} // namespace sbrt
