/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   First hits of every pixel's ray with the exact tracer on all
 *            cores (backend=cpu, and the reference of the GPU path)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CPU_TRACING_HPP
#define SBRT_CPU_TRACING_HPP

#include <vector>

#include "hit_image.hpp"

namespace sbrt {

/// Tile side (pixels) and node budget of the coarse first pass. Measured on
/// models A to C at 1056 x 884: tiles of 4 pixels cost more than they save
/// (0.6x on A); 8 and 16, with budgets of 16 to 64, are within noise.
constexpr int FIRST_PASS_TILE = 8, FIRST_PASS_BUDGET = 32;

/// What the coarse first pass did: its tiles, those whose rays all meet
/// nothing (not walked at all), its time.
struct FirstPassReport {
    size_t tiles = 0, empty_tiles = 0;
    double ms = 0;
};

/// Hits of camera.ray(r, c), row-major; `threads` 0 means all cores. With
/// `first_pass` (and the tracer's pyramid) each ray starts where the coarse
/// first pass (FirstHitBounds) puts its tile's first possible hit.
HitImage trace_image(const Tracer &tracer, const Camera &camera,
                     unsigned threads = 0, bool first_pass = true,
                     FirstPassReport *report = nullptr);

} // namespace sbrt

#endif
