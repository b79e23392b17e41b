/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Multithreaded CPU tracing of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "cpu_tracing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "first_hit_bounds.hpp"
#include "parallel.hpp"

namespace sbrt {

namespace {

/// Where the tracer draws only overlays, the pixels whose rays may hit
/// something: those the projections of their boxes cover; empty for all.
std::vector<uint8_t> pixels_to_trace(const Tracer &tracer, const Camera &camera)
{
    const int rows = camera.rows(), cols = camera.cols();
    const auto boxes = tracer.overlay_bounds();
    if (boxes.empty())
        return {};
    std::vector<uint8_t> mask(size_t(rows) * cols, 0);
    for (const auto &box : boxes) {
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 p(box[k & 1].x, box[(k >> 1) & 1].y, box[(k >> 2) & 1].z);
            double x, y;
            if (!camera.project(p, x, y))
                return {}; // the camera is among them
            x0 = std::min(x0, x);
            x1 = std::max(x1, x);
            y0 = std::min(y0, y);
            y1 = std::max(y1, y);
        }
        // pixel centres at ((c + 0.5) / cols * 2 - 1, 1 - (r + 0.5) / rows * 2);
        // one pixel of margin
        const int c0 = std::max(0, int(std::floor((x0 + 1) / 2 * cols - 0.5)) - 1);
        const int c1 = std::min(cols - 1, int(std::ceil((x1 + 1) / 2 * cols - 0.5)) + 1);
        const int r0 = std::max(0, int(std::floor((1 - y1) / 2 * rows - 0.5)) - 1);
        const int r1 = std::min(rows - 1, int(std::ceil((1 - y0) / 2 * rows - 0.5)) + 1);
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c)
                mask[size_t(r) * cols + c] = 1;
    }
    return mask;
}

} // namespace

HitImage trace_image(const Tracer &tracer, const Camera &camera, unsigned threads,
                     bool first_pass, FirstPassReport *report)
{
    HitImage hits(size_t(camera.rows()) * camera.cols());
    const std::vector<uint8_t> mask = pixels_to_trace(tracer, camera);
    // no pyramid (skipping off, the model not drawn): every bound is 0
    const auto start = std::chrono::steady_clock::now();
    const FirstHitBounds bounds =
        first_pass
            ? FirstHitBounds(tracer, camera, FIRST_PASS_TILE, FIRST_PASS_BUDGET, threads)
            : FirstHitBounds(camera);
    if (report)
        *report = {bounds.tiles(), bounds.empty_tiles(),
                   std::chrono::duration<double, std::milli>(
                       std::chrono::steady_clock::now() - start)
                       .count()};
    for_each_row(camera.rows(), threads, [&](int row) {
        for (int col = 0; col < camera.cols(); ++col) {
            const size_t i = size_t(row) * camera.cols() + col;
            if (!mask.empty() && !mask[i]) {
                hits[i] = Hit();
                continue;
            }
            const Ray ray = camera.ray(row, col);
            hits[i] = tracer.trace(ray, bounds.t_start(row, col, ray));
        }
    });
    return hits;
}

} // namespace sbrt
