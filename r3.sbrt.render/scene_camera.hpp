/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The camera of a request, defaults framing the whole model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SCENE_CAMERA_HPP
#define R3_SBRT_SCENE_CAMERA_HPP

#include "scene/camera.hpp"
#include "render_options.hpp"
#include "frame/coordinate_frame.hpp"

/// An error unless an image of rows x cols of `request` fits in this
/// machine's available memory (sbrt::check_image_fits: the streamed bands,
/// the kernel's window, an annotated PNG's whole image).
void check_image_fits(const RenderRequest &request, int rows, int cols);
/// Bytes the image of `request` takes while it is rendered (as
/// check_image_fits counts them): size= pixels, or for view=top the cells
/// of `region`.
double image_memory(const RenderRequest &request, const struct Cell_head &region);

/// Camera of the request: size= pixels, or for view=top one pixel per
/// cell of the current region.
sbrt::Camera make_camera(const RenderRequest &request, const sbrt::Model &model,
                         const sbrt::CoordinateFrame &frame,
                         const struct Cell_head &region);

#endif
