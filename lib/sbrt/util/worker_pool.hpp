/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Threads kept from frame to frame: rows of an image go to the
 *            workers in takes of consecutive rows, no thread is started
 *            per frame, and what a worker keeps in thread_local storage
 *            stays warm
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_WORKER_POOL_HPP
#define SBRT_WORKER_POOL_HPP

#include <atomic>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sbrt {

/// \brief `threads` workers (0: all cores): the caller of for_each_row and
/// threads - 1 threads of the pool's own, started once, pinned nowhere.
/// One job at a time (calls from several threads take turns).
class WorkerPool {
public:
    explicit WorkerPool(unsigned threads = 0);
    ~WorkerPool();
    WorkerPool(const WorkerPool &) = delete;
    WorkerPool &operator=(const WorkerPool &) = delete;

    unsigned size() const { return unsigned(threads_.size()) + 1; }

    /// Calls take_function(take_first, take_end, worker) for takes of rows
    /// covering [first, last), up to `most` rows a take (dynamic
    /// scheduling, rows_to_take), worker in [0, size()): 0 is the caller.
    /// Returns when every row is done; the first exception thrown on any
    /// worker stops the others taking rows and is rethrown here.
    void for_each_take(int first, int last,
                       const std::function<void(int take_first, int take_end, unsigned worker)>
                           &take_function,
                       int most);

    /// for_each_take with row_function(row, worker) called for each row
    /// of a take, in order.
    void for_each_row(int first, int last,
                      const std::function<void(int row, unsigned worker)> &row_function,
                      int most = 1);

    /// Per worker, the milliseconds spent in take_function during the
    /// last for_each_take.
    const std::vector<double> &busy_ms() const { return busy_ms_; }

private:
    void work(unsigned worker);
    void run_rows(unsigned worker);

    std::mutex job_mutex_; ///< one job at a time
    std::mutex mutex_;
    std::condition_variable start_, done_;
    long long generation_ = 0; ///< which job the workers are on
    unsigned running_ = 0;     ///< pool threads still in the job
    bool closing_ = false;
    const std::function<void(int, int, unsigned)> *function_ = nullptr;
    std::atomic<long long> next_{0};
    int last_ = 0;
    int most_ = 1; ///< the most rows a worker takes at once
    std::exception_ptr error_;
    std::vector<double> busy_ms_;
    std::vector<std::thread> threads_;
};

} // namespace sbrt

#endif
