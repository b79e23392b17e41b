/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   color= and rules=: material colours from a GRASS colour table
 *            instead of the stored ones
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_MATERIAL_COLORS_HPP
#define R3_SBRT_MATERIAL_COLORS_HPP

#include <vector>

#include "model/model.hpp"
#include "render_options.hpp"

/// Recolours every material of `materials` (a model's, EMPTY first) when
/// the request has color= or rules= (over the range of the class ids, as
/// r3.colors does).
void apply_color_option(const RenderRequest &request, std::vector<sbrt::Material> &materials);

#endif
