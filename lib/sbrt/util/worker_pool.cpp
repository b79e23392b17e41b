/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Threads kept from frame to frame
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/worker_pool.hpp"

#include <chrono>

#include "util/parallel.hpp"

namespace sbrt {

WorkerPool::WorkerPool(unsigned threads) : busy_ms_(thread_count(threads), 0.0)
{
    const unsigned n = thread_count(threads);
    threads_.reserve(n - 1);
    for (unsigned w = 1; w < n; ++w)
        threads_.emplace_back([this, w] { work(w); });
}

WorkerPool::~WorkerPool()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
    }
    start_.notify_all();
    for (std::thread &t : threads_)
        t.join();
}

void WorkerPool::run_rows(unsigned worker)
{
    using Clock = std::chrono::steady_clock;
    double busy = 0;
    try {
        take_rows(next_, last_, size(), most_, [&](long long first, long long end) {
            const auto start = Clock::now();
            (*function_)(int(first), int(end), worker);
            busy += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        });
    }
    catch (...) {
        next_ = last_; // the others stop at their next take
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!error_)
            error_ = std::current_exception();
    }
    busy_ms_[worker] = busy; // read by the caller once every worker is done
}

void WorkerPool::work(unsigned worker)
{
    long long seen = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return closing_ || generation_ != seen; });
            if (closing_)
                return;
            seen = generation_;
        }
        run_rows(worker);
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            --running_;
        }
        done_.notify_all();
    }
}

void WorkerPool::for_each_row(int first, int last,
                              const std::function<void(int, unsigned)> &row_function, int most)
{
    for_each_take(
        first, last,
        [&](int take_first, int take_end, unsigned worker) {
            for (int row = take_first; row < take_end; ++row)
                row_function(row, worker);
        },
        most);
}

void WorkerPool::for_each_take(int first, int last,
                               const std::function<void(int, int, unsigned)> &take_function,
                               int most)
{
    const std::lock_guard<std::mutex> job(job_mutex_);
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        function_ = &take_function;
        // 64 bits: every worker takes up to `most` past `last`, which must
        // not wrap
        next_ = first;
        last_ = last;
        most_ = most;
        error_ = nullptr;
        running_ = unsigned(threads_.size());
        ++generation_;
    }
    start_.notify_all();
    run_rows(0);
    std::exception_ptr error;
    {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return running_ == 0; });
        function_ = nullptr;
        error = error_;
    }
    if (error)
        std::rethrow_exception(error);
}

} // namespace sbrt
