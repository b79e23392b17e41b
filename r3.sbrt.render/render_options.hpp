/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request as its parts: each part (input, outputs,
 *            camera, shading, strata, sections, boreholes, drape, property,
 *            backend, detail, animation) defines its options, reads and checks its
 *            answers and gives the key of what it holds beside the set-up
 *            code that consumes it; one parse of a request's words serves
 *            the command line (G_parser's answers) and the view server
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RENDER_OPTIONS_HPP
#define R3_SBRT_RENDER_OPTIONS_HPP

#include <optional>
#include <string>
#include <vector>

#include "animation_part.hpp"
#include "backend_part.hpp"
#include "boreholes_part.hpp"
#include "camera_part.hpp"
#include "detail_part.hpp"
#include "drape_part.hpp"
#include "input_part.hpp"
#include "option_table.hpp"
#include "outputs_part.hpp"
#include "property_part.hpp"
#include "sections_part.hpp"
#include "shading_part.hpp"
#include "strata_part.hpp"

/// \brief Everything the user asked for, validated, map units: the parts
/// together (a stage of RenderSession keys on the parts it consumes).
struct RenderRequest : InputPart,
                       OutputsPart,
                       CameraPart,
                       ExaggerationPart,
                       ShadingPart,
                       ColorsPart,
                       StrataPart,
                       SectionsPart,
                       BoreholesPart,
                       DrapePart,
                       PropertyPart,
                       SelectionPart,
                       BackendPart,
                       DetailPart,
                       AnimationPart {
};

/// The keys of parts `Parts` of `request`, one line each: the key of a
/// stage that consumes those parts.
template <class... Parts>
std::string key_of(const RenderRequest &request)
{
    return ((static_cast<const Parts &>(request).key() + '\n') + ...);
}

/// The options of the module, as its parts define them (in the order of
/// the dialog and the manual).
OptionTable define_render_options();

/// \brief A request, or why the answers are not one (errors as values: the
/// command line fails with the message, the view server replies with it).
struct ParsedRequest {
    std::optional<RenderRequest> request;
    std::string error;
};

/// The request of `words` ("key=value", "-flags": a command line as
/// G_parser answered it, OptionTable::parsed_words, or a view server's
/// request line), checked by `options` as G_parser checks and by each part.
ParsedRequest parse_render_request(const OptionTable &options,
                                   const std::vector<std::string> &words);

#endif
