/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Multithreaded CPU tracing of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "cpu_tracing.hpp"

#include "parallel.hpp"

namespace sbrt {

std::vector<Hit> trace_image(const Tracer &tracer, const Camera &camera,
                             unsigned threads)
{
    std::vector<Hit> hits(size_t(camera.rows()) * camera.cols());
    for_each_row(camera.rows(), threads, [&](int row) {
        for (int col = 0; col < camera.cols(); ++col)
            hits[size_t(row) * camera.cols() + col] =
                tracer.trace(camera.ray(row, col));
    });
    return hits;
}

} // namespace sbrt
