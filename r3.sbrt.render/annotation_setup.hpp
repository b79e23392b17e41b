/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   What the PNG of a request is annotated with
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_ANNOTATION_SETUP_HPP
#define R3_SBRT_ANNOTATION_SETUP_HPP

#include "scene/camera.hpp"
#include "grass.hpp"
#include "png_annotations.hpp"
#include "render_options.hpp"
#include "frame/coordinate_frame.hpp"
#include "shading/property_paint.hpp"

/// The legend (every class of the prepared model; the PNG keeps those the
/// image shows), the north arrow where north points on the image, the
/// vertical exaggeration of 3D views and the scale bar of top views (cells
/// of `region`); nothing with -n or without png=.
PngAnnotations make_annotations(const RenderRequest &request, const sbrt::Model &model,
                                const sbrt::CoordinateFrame &frame,
                                const sbrt::Camera &camera,
                                const struct Cell_head &region,
                                const sbrt::PropertyPaint *property = nullptr,
                                const sbrt::UncertaintyFade *fade = nullptr);

#endif
