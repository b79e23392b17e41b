/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The module's options and what a run asks for
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROFILE_REQUEST_HPP
#define R3_SBRT_PROFILE_REQUEST_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "grass.hpp"
#include "output_format.hpp"

struct ProfileOptions {
    Option *input, *coordinates, *line, *cat, *output, *resolution, *png, *zexag, *width,
        *format, *nprocs, *memory;
    Flag *shell;
};

/// \brief What a run asks for, read from the options.
struct ProfileRequest {
    std::string input;
    std::vector<glm::dvec2> vertices; ///< from coordinates=, or empty
    std::string line;                 ///< line=: a vector map, or empty
    std::optional<int> cat;           ///< the line's category in layer 1
    std::string output;               ///< the class profile map, or empty
    std::optional<double> resolution; ///< its step along the line
    std::string png;                  ///< the figure, or empty
    std::optional<double> zexag;      ///< the figure's
    int width = 1000;                 ///< the figure's plot, in pixels
    /// -g or format=: the figure's and map's geometry (shell or json), or none
    sbrt_grass::OutputFormat print = sbrt_grass::OutputFormat::none;
    unsigned threads = 1; ///< nprocs= (reading the SBRT)
    uint64_t memory_bytes = 0; ///< memory=: this process with the blocks it holds
};

ProfileOptions define_profile_options();
/// The request; a fatal error for values the parser lets through but the
/// profile cannot take (a resolution or exaggeration not above 0).
ProfileRequest read_profile_request(const ProfileOptions &o);

#endif
