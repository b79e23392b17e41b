/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   GRASS headers for C++ (GRASS 8.2 has no extern "C" guards)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRASS_HPP
#define SBRT_GRASS_HPP

extern "C" {
#include <grass/gis.h>
#include <grass/raster.h>
#include <grass/raster3d.h>
#include <grass/colors.h>
#include <grass/glocale.h>
#include <grass/spawn.h>
}

#endif
