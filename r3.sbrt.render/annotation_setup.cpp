/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   What the PNG of a request is annotated with
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "annotation_setup.hpp"

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "property_colors.hpp"
#include "shading/shading.hpp"

namespace {

/// Where north points on the image at the model's centre (x right, y
/// down), if the camera sees it.
std::optional<glm::dvec2> north_on_image(const sbrt::CoordinateFrame &frame,
                                         const sbrt::Camera &camera)
{
    // a point ahead of the camera, at the depth of the model's centre
    const glm::dvec3 ahead = camera.forward();
    double depth = glm::dot(frame.centre() - camera.origin(), ahead);
    if (!(depth > 0))
        depth = frame.radius();
    const glm::dvec3 p = camera.origin() + depth * ahead;
    const glm::dvec3 q = p + glm::dvec3(0, 0.01 * frame.radius(), 0);
    double px, py, qx, qy;
    if (!camera.project(p, px, py) || !camera.project(q, qx, qy))
        return std::nullopt;
    // normalised device coordinates -> pixels (rows grow downwards)
    const glm::dvec2 d((qx - px) * camera.cols(), -(qy - py) * camera.rows());
    const double length = glm::length(d);
    if (!(length > 1e-9))
        return std::nullopt;
    return d / length;
}

} // namespace

PngAnnotations make_annotations(const RenderRequest &request, const sbrt::Model &model,
                                const sbrt::CoordinateFrame &frame,
                                const sbrt::Camera &camera,
                                const struct Cell_head &region,
                                const sbrt::PropertyPaint *property,
                                const sbrt::UncertaintyFade *fade)
{
    PngAnnotations a;
    // a tile's PNG is plain: tiles mosaic to the whole image
    if (request.png.empty() || !request.annotate || request.tile)
        return a;
    const std::string input = request.input;
    a.title = input.substr(0, input.find('@'));
    if (property) { // a colour bar of the property instead of the classes
        ColorBar bar;
        bar.name = request.property_title();
        const std::vector<size_t> &summed = property->summed();
        const sbrt::ChannelInfo &first = property->channels().info(summed[0]);
        if (summed.size() == 1)
            bar.long_name = first.long_name;
        else
            bar.long_name = "sum of " + std::to_string(summed.size()) + " channels";
        // "%" for a sum of probabilities, whatever unit the file gives
        bar.unit = property_unit(property->channels(), summed);
        const sbrt::ColorRamp &ramp = property->ramp();
        bar.low = ramp.low();
        bar.high = ramp.high();
        for (int k = 0; k < 256; ++k)
            bar.colors.push_back(ramp.rgb_at(bar.low + (bar.high - bar.low) * k / 255.0));
        a.bar = bar;
    }
    else
        for (size_t i = 1; i < model.materials().size(); ++i) {
            const sbrt::Material &m = model.materials()[i];
            a.classes.push_back({m.id, m.label, sbrt::material_color(model, uint32_t(i))});
        }
    // what select= and fade= did to the colours, below the legend
    std::string caption;
    if (!request.select.empty())
        caption = "only voxels where " + request.select;
    if (fade) {
        char text[256];
        std::snprintf(text, sizeof text, "greyer: more uncertain (%s %g to %g)",
                      request.fade.c_str(), fade->low(), fade->high());
        caption += (caption.empty() ? "" : "; ") + std::string(text);
    }
    // a coarse frame is never shown as if it were exact
    const std::string coarse = request.coarse_note();
    if (!coarse.empty())
        caption += (caption.empty() ? "" : "; ") + coarse;
    a.caption = caption;
    a.north = north_on_image(frame, camera);
    if (request.view.kind != sbrt::ViewKind::top) {
        a.zexag = request.zexag;
        return a;
    }
    // metres per cell across the middle of the region
    const double y = (region.north + region.south) / 2;
    if (G_projection() == PROJECTION_XY) {
        a.metres_per_pixel = region.ew_res;
        a.scale_in_metres = false;
    }
    else {
        G_begin_distance_calculations();
        a.metres_per_pixel = G_distance(region.west, y, region.west + region.ew_res, y);
    }
    return a;
}
