/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The sampled method volume renderers use, over the same SBRT:
 *            a ray marches in fixed steps (or coarse steps refined near
 *            the first solid sample) and stops at the first solid sample.
 *            For measuring what sampling costs against the exact tracer.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SAMPLED_TRACER_HPP
#define SBRT_SAMPLED_TRACER_HPP

#include <vector>

#include "tracing/hit_image.hpp"

namespace sbrt {

/// \brief Step lengths in cells (local units: a cell is 1 in x and y, a
/// voxel 1 in z). `fine_step` > 0 makes it adaptive: march with `step`
/// until a sample is solid, go back one step, march on with `fine_step`.
struct Sampling {
    double step = 1;
    double fine_step = 0;
};

/// The first solid sample of the ray (material, t, the face its step
/// crossed last), drawing the tracer's model (no planes, no translucency,
/// no overlays); samples at the middle of each step.
Hit sample_ray(const Tracer &tracer, const Ray &ray, const Sampling &sampling);

/// sample_ray for every pixel, row-major, on `threads` threads (0: all).
HitImage sample_image(const Tracer &tracer, const Camera &camera,
                      const Sampling &sampling, unsigned threads = 0);

} // namespace sbrt

#endif
