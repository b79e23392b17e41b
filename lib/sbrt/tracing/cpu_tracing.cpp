/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Multithreaded CPU tracing of the rows of an image
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/cpu_tracing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "util/parallel.hpp"

namespace sbrt {

std::vector<glm::dvec2> projected_corners(const std::array<glm::dvec3, 2> &box,
                                          const Camera &camera, int &behind)
{
    std::vector<glm::dvec2> corners;
    behind = 0;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p(box[k & 1].x, box[(k >> 1) & 1].y, box[(k >> 2) & 1].z);
        double x, y;
        if (camera.project(p, x, y))
            corners.emplace_back(x, y);
        else
            ++behind;
    }
    return corners;
}

std::optional<std::vector<PixelRect>> pixel_rects_of(
    const std::vector<std::array<glm::dvec3, 2>> &boxes, const Camera &camera)
{
    const int rows = camera.rows(), cols = camera.cols();
    std::vector<PixelRect> rects;
    for (const auto &box : boxes) {
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        int behind = 0;
        for (const glm::dvec2 &p : projected_corners(box, camera, behind)) {
            x0 = std::min(x0, p.x);
            x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y);
            y1 = std::max(y1, p.y);
        }
        if (behind == 8)
            continue; // wholly behind a perspective camera: no ray goes there
        if (behind > 0)
            return std::nullopt; // the camera is among them: any pixel may
        // pixel centres at ((c + 0.5) / cols * 2 - 1, 1 - (r + 0.5) / rows * 2);
        // one pixel of margin; clamped before the conversion to int (a box
        // far outside the frame projects far outside any int)
        auto pixel = [](double v, double high) {
            return int(std::clamp(v, -2.0, high + 2));
        };
        const int c0 = std::max(0, pixel(std::floor((x0 + 1) / 2 * cols - 0.5), cols) - 1);
        const int c1 = std::min(cols - 1, pixel(std::ceil((x1 + 1) / 2 * cols - 0.5), cols) + 1);
        const int r0 = std::max(0, pixel(std::floor((1 - y1) / 2 * rows - 0.5), rows) - 1);
        const int r1 = std::min(rows - 1, pixel(std::ceil((1 - y0) / 2 * rows - 0.5), rows) + 1);
        if (r0 <= r1 && c0 <= c1)
            rects.push_back({r0, r1, c0, c1});
    }
    return rects;
}

std::vector<std::pair<int, int>> row_spans(const std::vector<PixelRect> &rects, int row)
{
    std::vector<std::pair<int, int>> spans;
    for (const auto &[r0, r1, c0, c1] : rects)
        if (row >= r0 && row <= r1)
            spans.emplace_back(c0, c1);
    std::sort(spans.begin(), spans.end());
    std::vector<std::pair<int, int>> merged;
    for (const auto &span : spans) {
        if (!merged.empty() && span.first <= merged.back().second + 1)
            merged.back().second = std::max(merged.back().second, span.second);
        else
            merged.push_back(span);
    }
    return merged;
}

CpuRowTracer::CpuRowTracer(const Tracer &tracer, const Camera &camera,
                           unsigned threads, bool first_pass, WorkerPool *pool)
    : tracer_(tracer), camera_(camera), threads_(threads)
{
    // the overlays' columns of each row, found once (a row is traced block
    // by block)
    const std::optional<std::vector<PixelRect>> rects =
        tracer.overlay_bounds().empty() ? std::nullopt
                                        : pixel_rects_of(tracer.overlay_bounds(), camera);
    if (rects) {
        overlay_spans_.emplace(size_t(camera.rows()));
        for (int row = 0; row < camera.rows(); ++row)
            (*overlay_spans_)[size_t(row)] = row_spans(*rects, row);
    }
    // no pyramid (skipping off, the model not drawn): every bound is 0
    const auto start = std::chrono::steady_clock::now();
    if (first_pass && pool)
        bounds_.emplace(tracer, camera, FIRST_PASS_TILE, FIRST_PASS_BUDGET, *pool);
    else if (first_pass)
        bounds_.emplace(tracer, camera, FIRST_PASS_TILE, FIRST_PASS_BUDGET, threads);
    else
        bounds_.emplace(camera);
    report_ = {bounds_->tiles(), bounds_->empty_tiles(),
               std::chrono::duration<double, std::milli>(
                   std::chrono::steady_clock::now() - start)
                   .count()};
}

void CpuRowTracer::trace_span(int row, int c0, int c1, Hit *out) const
{
    StackPin pin; // a paged model's block, from ray to ray
    const auto trace = [&](int col) {
        if (bounds_->meets_nothing(row, col)) {
            out[col] = Hit(); // what trace() returns for a t_start of inf
            return;
        }
        const Ray ray = camera_.ray(row, col);
        tracer_.trace_into(ray, bounds_->t_start(row, col, ray), out[col], pin);
    };
    if (!overlay_spans_) {
        for (int col = c0; col < c1; ++col)
            trace(col);
        return;
    }
    // the columns of the rectangles across this row, overlaps merged
    std::fill(out + c0, out + c1, Hit());
    for (const auto &[s0, s1] : (*overlay_spans_)[size_t(row)])
        for (int col = std::max(c0, s0); col <= std::min(c1 - 1, s1); ++col)
            trace(col);
}

void CpuRowTracer::trace_rows(int first, int count, Hit *out)
{
    const int cols = camera_.cols();
    for_each_take(first, first + count, threads_, ROWS_PER_TAKE, [&](int take_first, int end) {
        for_each_block(take_first, end, cols, [&](int row, int c0, int c1) {
            trace_span(row, c0, c1, out + size_t(row - first) * size_t(cols));
        });
    });
}

HitImage trace_image(const Tracer &tracer, const Camera &camera, unsigned threads,
                     bool first_pass, FirstPassReport *report)
{
    HitImage hits(size_t(camera.rows()) * camera.cols());
    CpuRowTracer rows(tracer, camera, threads, first_pass);
    if (report)
        *report = rows.first_pass();
    rows.trace_rows(0, camera.rows(), hits.data());
    return hits;
}

} // namespace sbrt
