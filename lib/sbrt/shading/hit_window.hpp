/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A sliding window of traced image rows: what image-space
 *            kernel normals need around a band (its halo), never the
 *            whole image unless the kernel reaches that far
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_HIT_WINDOW_HPP
#define SBRT_HIT_WINDOW_HPP

#include <deque>
#include <utility>
#include <vector>

#include "tracing/cpu_tracing.hpp"

namespace sbrt {

/// \brief Rows [first(), last()) of an image, traced when first covered;
/// rows dropped and covered again are traced again (the same hits).
class HitWindow {
public:
    /// One traced row and what the kernel has made of it so far.
    struct Row {
        HitImage hits;
        std::vector<double> depth;     ///< view depth per pixel (empty: not yet)
        std::pair<int, int> reach{-1, -1}; ///< rows the kernel reads (first < 0: not yet)
        bool kernel_done = false;      ///< hits' normals are the kernel's
        std::vector<glm::dvec3> across; ///< smoothing's first pass (empty: not yet)
    };

    HitWindow(RowTracer &tracer, int cols) : tracer_(tracer), cols_(cols) {}

    /// Makes [first, last) part of the window, tracing the rows it lacks
    /// (the window stays contiguous: a gap between is traced too).
    void cover(int first, int last);
    /// Drops the rows before `row`.
    void drop_before(int row);

    Row &row(int r) { return rows_[size_t(r - first_)]; }
    int first() const { return first_; }
    int last() const { return first_ + int(rows_.size()); }
    /// Most rows held at once so far.
    int most_rows() const { return most_rows_; }

private:
    std::vector<Row> trace(int first, int last);

    RowTracer &tracer_;
    int cols_;
    std::deque<Row> rows_;
    int first_ = 0, most_rows_ = 0;
};

} // namespace sbrt

#endif
