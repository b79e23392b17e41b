/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   The module's options and the request read from them
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_WHAT_REQUEST_HPP
#define R3_SBRT_WHAT_REQUEST_HPP

#include <string>
#include <cstdint>
#include <vector>

#include "grass.hpp"
#include "output_format.hpp"

/// \brief The options, as G_define_option made them.
struct WhatOptions {
    Option *input, *coordinates, *points, *layer, *where, *format, *separator, *output, *nprocs,
        *memory;
    Flag *voxels; ///< -v: the property channels voxel by voxel
};

/// \brief How the logs are written: plain, json or csv.
using LogFormat = sbrt_grass::OutputFormat;

/// \brief A point to query: map coordinates, and its category where it
/// comes from points= (-1 otherwise).
struct QueryPoint {
    double x = 0, y = 0;
    int cat = -1;
};

/// \brief What the user asked for.
struct WhatRequest {
    std::string input;
    std::vector<QueryPoint> coordinates; ///< from coordinates=
    std::string points;                  ///< a vector map, or empty
    std::string layer, where;
    LogFormat format = LogFormat::plain;
    char separator = ','; ///< of csv
    std::string output; ///< a file; empty or "-": standard output
    /// -v: the voxel rows of the property channels in plain and csv (json
    /// lists them under their own key whatever -v says)
    bool voxels = false;
    unsigned threads = 1; ///< nprocs= (reading the SBRT)
    uint64_t memory_bytes = 0; ///< memory=: this process with the blocks it holds
};

WhatOptions define_what_options();
/// The request of the parsed options (G_parser has checked the pairs of
/// coordinates= and the relations between the options).
WhatRequest read_what_request(const WhatOptions &options);

#endif
