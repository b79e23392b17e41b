/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   A new map's name checked before any work
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MAP_NAMES_HPP
#define SBRT_MAP_NAMES_HPP

namespace sbrt_grass {

/// Throws sbrt::Error, naming `option`, unless `name` is a legal GRASS
/// name short enough for a new SBRT (`sbrt`: its hidden sibling
/// `.name.tmp.PID` must fit a file name's 255 bytes) or 3D raster map, and
/// its path fits GRASS's path buffers.
void check_new_name(const char *name, bool sbrt, const char *option);

} // namespace sbrt_grass

#endif
