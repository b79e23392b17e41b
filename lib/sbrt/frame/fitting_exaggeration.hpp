/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The vertical exaggeration a model is drawn with when none is
 *            given: its thickness made a share of its width, rounded to a
 *            number a person would type
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FITTING_EXAGGERATION_HPP
#define SBRT_FITTING_EXAGGERATION_HPP

#include "model/model.hpp"

namespace sbrt {

/// Share of the horizontal size (the geometric mean of the two sides) that
/// the exaggerated thickness is made: at the default oblique view (30
/// degrees up) the sides then take about a third of the image's height.
constexpr double FITTED_THICKNESS_SHARE = 0.3;

/// The exaggeration of a box `width` x `depth` (map units) and `thickness`
/// thick: FITTED_THICKNESS_SHARE of sqrt(width * depth) over the thickness,
/// rounded in log scale to the nearest of 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8
/// times a power of ten; 1 for a box as thick as that already (never
/// flattened) or with no thickness.
double fitting_exaggeration(double width, double depth, double thickness);

/// The exaggeration of `model`: of its frame's extent, thick from its
/// bottom to its highest top.
double fitting_exaggeration(const Model &model);
/// The same of a model of `frame` whose highest top is `top_local` (local
/// height, as highest_top_local gives: from summaries, or a coarse level's
/// exact model).
double fitting_exaggeration(const Frame &frame, double top_local);

} // namespace sbrt

#endif
