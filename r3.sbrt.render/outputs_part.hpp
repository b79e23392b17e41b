/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's outputs: the image's maps and its PNG
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_OUTPUTS_PART_HPP
#define R3_SBRT_OUTPUTS_PART_HPP

#include <string>

#include "option_table.hpp"

/// \brief output=, material=, hit_elevation=, depth=, png= and -n (no key:
/// the session caches no output).
struct OutputsPart {
    std::string output, material, hit_elevation, depth, png;
    bool annotate = true; ///< the PNG's legend, north arrow, scale bar (not -n)

    static void define(OptionTable &table);
    void read(const Answers &answers);
};

#endif
