/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The profile's line: coordinates= as given, or the line of a
 *            vector map (its first, or the one of cat=)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_LINE_INPUT_HPP
#define R3_SBRT_LINE_INPUT_HPP

#include <vector>

#include <glm/vec2.hpp>

#include "profile_request.hpp"

/// The line's vertices in order; throws sbrt::Error where line= holds no
/// line (or none of cat=).
std::vector<glm::dvec2> read_line_vertices(const ProfileRequest &request);

#endif
