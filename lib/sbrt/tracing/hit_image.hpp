/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The hits of an image, one per pixel, row-major, allocated
 *            without a first pass that fills them: the threads that trace
 *            a row write its hits, so each page is touched once, by the
 *            thread that uses it (a 1056 x 884 image holds 67 MB of hits)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_HIT_IMAGE_HPP
#define SBRT_HIT_IMAGE_HPP

#include <vector>

#include "tracing/tracer.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

/// Hits of an image. HitImage(n) holds n unwritten hits: whoever makes one
/// writes every element (a pixel it does not trace gets Hit()).
using HitImage = std::vector<Hit, UnfilledAllocator<Hit>>;

} // namespace sbrt

#endif
