/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A view server's request line read into a typed request: the
 *            protocol's framing (one line of text, no NUL byte, a verb),
 *            the words answered as the command line's options, and the
 *            checks the command line makes; errors as sbrt::Error. Shared
 *            by the view server and its fuzz target
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_REQUEST_LINE_HPP
#define R3_SBRT_REQUEST_LINE_HPP

#include <cstdint>
#include <string>

#include "render_options.hpp"

/// \brief What a request line asks for.
struct RequestLine {
    enum class Verb { render, classes, pick, quit } verb = Verb::quit;
    RenderRequest request; ///< with render, classes and pick
    int pick_row = 0, pick_col = 0; ///< with pick: the pixel of the view
};

/// \brief Reads request lines against the module's options (nothing of
/// GRASS's parser state is written: each line is parsed as words).
class RequestLineReader {
public:
    /// memory= of a request that gives none is found here, once: it is
    /// part of the model's key, and the memory available changes as the
    /// server holds blocks (found again each line, it reread the model).
    explicit RequestLineReader(const OptionTable &options);

    /// The request of `line` (its end of line taken off); throws
    /// sbrt::Error naming what is wrong: a NUL byte, an empty line, an
    /// unknown verb, an unknown, repeated or refused option (outputs,
    /// frames=, tile=, rules=-), or a value the command line refuses.
    /// "pick ROW COL key=value..." asks what the view's pixel (ROW, COL)
    /// hits.
    RequestLine read(const std::string &line);

private:
    const OptionTable &options_;
    uint64_t default_memory_;
};

#endif
