/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Runs a function on every row of an image with a pool of
 *            threads taking rows from an atomic counter
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PARALLEL_HPP
#define SBRT_PARALLEL_HPP

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace sbrt {

/// Calls row_function(row) for row in [0, rows) on `threads` threads
/// (0: all cores); returns when all rows are done.
template <typename RowFunction>
void for_each_row(int rows, unsigned threads, const RowFunction &row_function)
{
    if (threads == 0)
        threads = std::max(1u, std::thread::hardware_concurrency());
    std::atomic<int> next{0};
    auto work = [&]() {
        for (int row; (row = next++) < rows;)
            row_function(row);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads && t < unsigned(rows); ++t)
        pool.emplace_back(work);
    work();
    for (std::thread &t : pool)
        t.join();
}

} // namespace sbrt

#endif
