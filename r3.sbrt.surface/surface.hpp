/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * PURPOSE:   What the module is asked (options read into a request), and
 *            the job that makes the maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SURFACE_HPP
#define R3_SBRT_SURFACE_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "grass.hpp"

/// \brief The maps to make of one class set, names empty where not asked.
struct SurfaceRequest {
    std::string input;
    std::vector<std::string> classes;
    std::string top, base, thickness, layers, depth;
    /// expected_thickness= of probability= (channels in %, summed)
    std::string probability, expected_thickness;
    unsigned threads = 0; ///< 0: all cores
    /// memory= in bytes: the model is read band by band within it
    /// (expected_thickness= reads it whole: its channels lie by columns)
    uint64_t memory = uint64_t(300) << 20;
};

/// Reads the SBRT, measures the class set in every region cell (sampled
/// at the cell's centre in the model's grid) and writes the maps asked
/// for, with metadata, history and colour tables. Throws sbrt::Error.
void make_surfaces(const SurfaceRequest &request);

#endif
