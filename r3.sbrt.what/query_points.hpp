/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   The points of a vector map to query (layer=, where=)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_WHAT_QUERY_POINTS_HPP
#define R3_SBRT_WHAT_QUERY_POINTS_HPP

#include <vector>

#include "what_request.hpp"

/// The points of the request: coordinates= as given, or the points of
/// points= in layer= (all layers for -1) that where= selects, in the
/// map's order. Throws sbrt::Error where the map is missing, holds no such
/// points (a map of lines or areas) or where= fails.
std::vector<QueryPoint> query_points(const WhatRequest &request);

#endif
