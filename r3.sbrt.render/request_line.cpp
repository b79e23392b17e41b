/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A view server's request line read into a typed request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "request_line.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "request_error.hpp"
#include "util/available_memory.hpp"
#include "util/error.hpp"

namespace {

/// Options that name outputs of the command line: a view server's frame
/// is its reply.
const char *const OUTPUT_KEYS[] = {"output", "material", "hit_elevation", "depth", "value", "png",
                                   "strds", "video"};

/// memory= of a request that gives none: frames follow one another, and a
/// budget below the blocks they reach decodes those again for every frame
/// (a national model's orbit frames within 300 MB: docs/performance.md).
/// A quarter of the memory this process can have, at least GRASS's 300 MB.
uint64_t view_server_memory()
{
    const uint64_t least = uint64_t(300) << 20;
    return std::max(least, uint64_t(sbrt::available_memory() / 4));
}

} // namespace

RequestLineReader::RequestLineReader(const OptionTable &options)
    : options_(options), default_memory_(view_server_memory())
{
}

RequestLine RequestLineReader::read(const std::string &line)
{
    if (line.find('\0') != std::string::npos)
        bad_request(_("the request holds a NUL byte; a request is one line of text"));
    std::vector<std::string> words = split_words(line);
    if (words.empty())
        bad_request(_("empty request: render key=value..., classes input=NAME, "
                      "pick ROW COL key=value... or quit"));
    RequestLine out;
    if (words[0] == "quit")
        return out;
    if (words[0] != "render" && words[0] != "classes" && words[0] != "pick")
        bad_request(_("unknown request <%s>: render, classes, pick or quit"),
                    shortened(words[0], 100).c_str());
    out.verb = words[0] == "render"    ? RequestLine::Verb::render
               : words[0] == "classes" ? RequestLine::Verb::classes
                                       : RequestLine::Verb::pick;
    words.erase(words.begin());
    if (out.verb == RequestLine::Verb::pick) {
        // the pixel: two whole numbers before the options
        auto pixel = [&](const char *what) {
            if (words.empty())
                bad_request(_("pick: give the pixel's row and column, then the view's "
                              "options"));
            char *end = nullptr;
            const long v = std::strtol(words[0].c_str(), &end, 10);
            if (words[0].empty() || *end || v < 0 || v > 1000000)
                bad_request(_("pick: %s <%s> is not a pixel index"), what,
                            shortened(words[0], 100).c_str());
            words.erase(words.begin());
            return int(v);
        };
        out.pick_row = pixel("row");
        out.pick_col = pixel("column");
    }
    for (const char *key : OUTPUT_KEYS)
        for (const std::string &word : words)
            if (word.compare(0, std::strlen(key) + 1, std::string(key) + "=") == 0)
                bad_request(_("%s= names an output of the command line; the view "
                              "server's frame is its reply"),
                            key);
    ParsedRequest parsed = parse_render_request(options_, words);
    if (!parsed.request)
        throw sbrt::Error(parsed.error);
    // one frame of a view: what makes sequences and tiles, and rules from
    // stdin (the requests' stream), is the command line's
    if (parsed.request->frames != 1 || parsed.request->tile || parsed.request->rules == "-")
        bad_request(_("frames=, tile= and rules=- are for the command line, not the "
                      "view server"));
    out.request = std::move(*parsed.request);
    if (!out.request.memory_given)
        out.request.memory_bytes = default_memory_;
    return out;
}
