/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What the tracer's two halves share (tracer.cpp: the walk
 *            through the cells and stacks; tracer_overlays.cpp: boreholes
 *            and fence curtains): a ray on its way, the surface it enters
 *            a stretch through, an overlay it meets. Private to lib/sbrt.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TRACER_WALK_HPP
#define SBRT_TRACER_WALK_HPP

#include <algorithm>
#include <limits>

#include "tracing/tracer.hpp"

namespace sbrt {

namespace tracer_detail {

constexpr double INF = std::numeric_limits<double>::infinity();
/// Marks a fence panel in a cell's overlay list (else a borehole).
constexpr uint32_t PANEL = Tracer::OVERLAY_PANEL;
/// Up to this many overlays, a ray without the model meets each of them
/// directly rather than walking the cells between them.
constexpr size_t DIRECT_OVERLAYS = 256;

/// Whether a ray whose height runs from z_a to z_b stays out of `range`:
/// at or above its top (as walk_stack reads a stack) or below its bottom.
inline bool passes(const ZRange &range, double z_a, double z_b)
{
    return range.empty() || std::min(z_a, z_b) >= double(range.high) ||
           std::max(z_a, z_b) < double(range.low);
}

/// Face through which a ray moving along `axis` with sign of `d` enters.
inline Face entry_face(int axis, double d)
{
    if (axis == 0)
        return d > 0 ? Face::west : Face::east;
    if (axis == 1)
        return d > 0 ? Face::south : Face::north;
    return d > 0 ? Face::bottom : Face::top;
}

} // namespace tracer_detail

/// The surface a ray enters a stretch through, with its shading normal
/// (a cell's faces leave it unset: face_normal gives it, at a hit only).
struct Tracer::Entry {
    Face face = Face::none;
    glm::dvec3 normal{0};
    int plane = -1;
};

/// One ray on its way: local origin and direction, what it met so far.
struct Tracer::Walk {
    const Ray &ray;
    glm::dvec3 o, d;      ///< local frame
    Hit &hit;             ///< written in place: the caller's hit
    StackPin &pin;        ///< a paged model's block the walk is in
    glm::dvec3 inv_d{0};  ///< 1 / d per axis (inf along a wall)
};

/// An overlay a ray meets: a borehole cylinder's span or a fence
/// curtain's point (start == end), with the surface's normal at its start.
struct Tracer::Event {
    double start, end;
    uint32_t item;
    glm::dvec3 normal;
};

} // namespace sbrt

#endif
