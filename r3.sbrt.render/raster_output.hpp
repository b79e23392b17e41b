/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Writes a rendered image as GRASS raster maps with colour
 *            tables, category labels and history
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RASTER_OUTPUT_HPP
#define R3_SBRT_RASTER_OUTPUT_HPP

#include "shading.hpp"
#include "render_options.hpp"

/// Writes <output>.red/.green/.blue and the optional maps of the request.
void write_image_maps(const RenderRequest &request, const sbrt::Model &model,
                      const sbrt::Image &image);

#endif
