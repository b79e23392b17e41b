/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Verbose messages: what the scene leaves out (hidden strata,
 *            stacks out of view or cut away) and the empty-space pyramid
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RENDER_SKIPPING_REPORT_HPP
#define R3_SBRT_RENDER_SKIPPING_REPORT_HPP

#include "tracing/scene_pruning.hpp"

/// Intervals and bytes hide= removed (the model as read against what is left).
void report_hidden(const sbrt::Model &read, const sbrt::Model &left, size_t hidden);
/// hide= applied while tracing: the strata crossed as air.
void report_hidden_while_tracing(size_t hidden);

/// What pruning left out (for the GPU: stacks out of the view and, with
/// `planes`, those cut away).
void report_pruning(const sbrt::Pruning &pruning, size_t planes);

/// The empty-space pyramid `p` over the model `m` that is drawn.
void report_pyramid(const sbrt::MinMaxPyramid &p, const sbrt::Model &m);

#endif
