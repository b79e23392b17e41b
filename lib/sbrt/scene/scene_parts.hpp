/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Parts of a scene made from what a user gives: a vertical
 *            section facing the camera, translucent strata, a borehole's
 *            stack from its logged intervals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SCENE_PARTS_HPP
#define SBRT_SCENE_PARTS_HPP

#include <utility>
#include <vector>

#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace sbrt {

/// The vertical section through map points a and b: a clip plane that
/// removes the side of the line the camera is on (its front, for a
/// parallel camera), so the cut face looks at the camera.
ClipPlane section_plane(glm::dvec2 a, glm::dvec2 b, const Camera &camera);

/// Materials (index, alpha 0..1 absorbed over `length` map units) made
/// translucent, in their colours; every other material opaque.
Translucency make_translucency(const Model &model,
                               const std::vector<std::pair<uint32_t, double>> &alphas,
                               double length);

/// \brief What the tops and bottoms of a borehole's log measure.
enum class LogReference { elevation, depth };

/// The reference a word names ("elevation", "depth"); sbrt::Error for any
/// other word.
LogReference parse_log_reference(const std::string &word);
const char *log_reference_name(LogReference reference);

/// A log's value as an elevation (map z): itself, or `collar` (the
/// elevation the depths are measured from) less it.
inline double log_elevation(double value, LogReference reference, double collar)
{
    return reference == LogReference::depth ? collar - value : value;
}

/// \brief One logged interval in elevations (map z), its material index.
struct LoggedInterval {
    double bottom, top;
    uint32_t material;
};

/// The stack of logged intervals in the model's local frame, bottom up:
/// gaps are empty; where two overlap, the lower one keeps the overlap;
/// materials in `hidden` are empty; equal neighbours merged; no empty
/// interval on top.
std::vector<Interval> log_stack(const Frame &frame, std::vector<LoggedInterval> logged,
                                const std::vector<uint32_t> &hidden);

} // namespace sbrt

#endif
