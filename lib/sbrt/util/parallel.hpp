/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Runs a function on every row of an image with a pool of
 *            threads taking rows from an atomic counter; an exception
 *            thrown on any thread reaches the caller
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PARALLEL_HPP
#define SBRT_PARALLEL_HPP

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace sbrt {

/// Threads to use for `threads` (0: all cores).
inline unsigned thread_count(unsigned threads)
{
    return threads ? threads : std::max(1u, std::thread::hardware_concurrency());
}

/// The most rows a tracing thread takes at once: a ray's neighbours in the
/// next row cross the cells it crossed, so a thread that traces a run of
/// consecutive rows finds them in its cache (a thread taking every 16th
/// row, as 16 threads taking one row at a time do, traced 1.2-1.5 times as
/// long on one core; in runs of 8, 1.05 times).
constexpr int ROWS_PER_TAKE = 8;

/// Rows a thread takes when `left` rows are left to `threads` threads, at
/// most `most`: fewer as the rows run out (half of a thread's share of
/// what is left), so that the threads end together.
inline int rows_to_take(long long left, unsigned threads, int most)
{
    return int(std::clamp<long long>(left / (2 * (long long)(std::max(1u, threads))), 1,
                                     std::max(1, most)));
}

/// One thread's share of rows [.., last) taken from `next` (shared by the
/// `threads` threads): take after take of up to `most` rows
/// (rows_to_take), take_function(first, end) called for each, until no row
/// is left.
template <typename TakeFunction>
void take_rows(std::atomic<long long> &next, long long last, unsigned threads, int most,
               const TakeFunction &take_function)
{
    for (;;) {
        const int take = rows_to_take(last - next.load(std::memory_order_relaxed), threads, most);
        const long long first = next.fetch_add(take);
        if (first >= last)
            return;
        take_function(first, std::min<long long>(first + take, last));
    }
}

/// Calls take_function(take_first, take_end) for takes of rows covering
/// [first, last) on `threads` threads (0: all cores), up to `most` rows a
/// take (rows_to_take); returns when all rows are done. The first
/// exception thrown by take_function, on any thread, stops the other
/// threads taking rows and is rethrown here (a thread never ends the
/// process with std::terminate).
template <typename TakeFunction>
void for_each_take(int first, int last, unsigned threads, int most,
                   const TakeFunction &take_function)
{
    threads = thread_count(threads);
    // 64 bits: every thread takes up to `most` past `last`, which must not
    // wrap
    std::atomic<long long> next{first};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&]() {
        try {
            take_rows(next, last, threads, most, [&](long long take_first, long long end) {
                take_function(int(take_first), int(end));
            });
        }
        catch (...) {
            next = last; // the others stop at their next take
            const std::lock_guard<std::mutex> lock(error_mutex);
            if (!error)
                error = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads && int(t) < last - first; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread &t : pool)
        t.join();
    if (error)
        std::rethrow_exception(error);
}

/// for_each_take with row_function(row) called for each row of a take, in
/// order.
template <typename RowFunction>
void for_each_row_in_runs(int first, int last, unsigned threads, int most,
                          const RowFunction &row_function)
{
    for_each_take(first, last, threads, most, [&](int take_first, int end) {
        for (int row = take_first; row < end; ++row)
            row_function(row);
    });
}

/// for_each_row_in_runs, a row at a time.
template <typename RowFunction>
void for_each_row(int first, int last, unsigned threads, const RowFunction &row_function)
{
    for_each_row_in_runs(first, last, threads, 1, row_function);
}

/// for_each_row over [0, rows).
template <typename RowFunction>
void for_each_row(int rows, unsigned threads, const RowFunction &row_function)
{
    for_each_row(0, rows, threads, row_function);
}

} // namespace sbrt

#endif
