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

/// Hits of camera.ray(r, c), row-major; `threads` 0 means all cores.
HitImage trace_image(const Tracer &tracer, const Camera &camera,
                     unsigned threads = 0);

} // namespace sbrt

#endif
