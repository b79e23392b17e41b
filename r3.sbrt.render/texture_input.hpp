/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Reading the drape texture: one raster map through its colour
 *            table, or three maps red, green, blue (0-255), at the first
 *            map's own resolution
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_TEXTURE_INPUT_HPP
#define R3_SBRT_TEXTURE_INPUT_HPP

#include <string>
#include <vector>

#include "shading/drape.hpp"

/// The texture of texture=; throws (bad_request) naming a missing map.
sbrt::Texture read_texture(const std::vector<std::string> &maps);

#endif
