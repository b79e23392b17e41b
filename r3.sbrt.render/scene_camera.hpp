/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The camera of a request, defaults framing the whole model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SCENE_CAMERA_HPP
#define R3_SBRT_SCENE_CAMERA_HPP

#include "scene/camera.hpp"
#include "render_options.hpp"
#include "tracing/tracer.hpp"

/// Fatal error unless an image of rows x cols fits in this machine's
/// memory (what the streamed bands take, or with `kernel_normals` the
/// kernel's window at its largest, the whole image; with a margin).
void check_image_fits(int rows, int cols, bool kernel_normals);

/// Camera of the request: size= pixels, or for view=top one pixel per
/// cell of the current region.
sbrt::Camera make_camera(const RenderRequest &request,
                         const sbrt::Tracer &tracer,
                         const struct Cell_head &region);

#endif
