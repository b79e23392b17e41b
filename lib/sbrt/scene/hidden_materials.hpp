/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Scene preparation: hidden materials become empty space, and
 *            the stacks shrink to what is left to draw (linear time)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_HIDDEN_MATERIALS_HPP
#define SBRT_HIDDEN_MATERIALS_HPP

#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// The model without the materials whose index is listed: their intervals
/// become EMPTY, merge with empty neighbours and vanish at a stack's top.
/// Material indices and the legend stay as they are.
Model hide_materials(const Model &model, const std::vector<uint32_t> &hidden);

} // namespace sbrt

#endif
