/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Reads the SBRT a render needs: for a top view that no part of
 *            outside the region can change, only the blocks of cells under
 *            the region
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_MODEL_READING_HPP
#define R3_SBRT_MODEL_READING_HPP

extern "C" {
#include <grass/gis.h>
}

#include "model/model.hpp"
#include "render_options.hpp"

/// Whether the render sees only the stacks under `region`: a single top
/// view (vertical rays through the region's cells) with no depth map (its
/// camera height follows the whole model's top), no boreholes and no fence
/// (they reach past the region).
bool sees_only_the_region(const RenderRequest &request);

/// Whether the request's model is read paged (sbrt::StackPages): the
/// CPU draws it (backend=cpu, or auto with no GPU device) and only its
/// rays read the stacks (no boreholes, fence, drape or property
/// channels). A top view of a region then decodes the blocks under it.
bool reads_pages(const RenderRequest &request);

/// The model of request.input: paged where reads_pages and its stacks are
/// format 2.1 (the budget memory= checked before a block is decoded); the
/// blocks under the region (grown by a cell) where sees_only_the_region;
/// else all of it.
sbrt::Model read_model(const RenderRequest &request, const struct Cell_head &region);

#endif
