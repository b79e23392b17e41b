/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sliding window of traced image rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/hit_window.hpp"

#include <algorithm>

namespace sbrt {

std::vector<HitWindow::Row> HitWindow::trace(int first, int last)
{
    HitImage hits(size_t(last - first) * cols_);
    tracer_.trace_rows(first, last - first, hits.data());
    std::vector<Row> rows(size_t(last - first));
    for (int r = first; r < last; ++r) {
        const auto begin = hits.begin() + ptrdiff_t(r - first) * cols_;
        rows[size_t(r - first)].hits.assign(begin, begin + cols_);
    }
    return rows;
}

void HitWindow::cover(int first, int last)
{
    if (first >= last)
        return;
    if (rows_.empty()) {
        for (Row &row : trace(first, last))
            rows_.push_back(std::move(row));
        first_ = first;
    }
    else {
        if (first < first_) {
            std::vector<Row> before = trace(first, first_);
            for (auto row = before.rbegin(); row != before.rend(); ++row)
                rows_.push_front(std::move(*row));
            first_ = first;
        }
        if (last > this->last())
            for (Row &row : trace(this->last(), last))
                rows_.push_back(std::move(row));
    }
    most_rows_ = std::max(most_rows_, int(rows_.size()));
}

void HitWindow::drop_before(int row)
{
    while (!rows_.empty() && first_ < row) {
        rows_.pop_front();
        ++first_;
    }
    if (rows_.empty())
        first_ = 0;
}

} // namespace sbrt
