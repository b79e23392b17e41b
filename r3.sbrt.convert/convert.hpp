/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   The conversions the module offers, one file each
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_CONVERT_HPP
#define R3_SBRT_CONVERT_HPP

#include <string>
#include <vector>

#include "classifier.hpp"
#include "model.hpp"

/// Frame of the current 3D region.
sbrt::Frame current_frame();

/// 3D raster (current 3D region) -> SBRT.
sbrt::Model voxels_to_sbrt(const char *input, sbrt::Classifier &classifier);

/// Stacked horizon rasters (top to bottom) -> SBRT with continuous heights.
sbrt::Model horizons_to_sbrt(const std::vector<std::string> &horizons,
                             const std::vector<int> &materials,
                             const char *bottom);

/// SBRT -> 3D raster in the current 3D region, with colours and labels.
void sbrt_to_voxels(const char *input, const char *output);

/// Prints the metadata and Table 1 figures (plain or key=value).
void print_report(const char *name, const sbrt::Model &model, bool shell);

#endif
