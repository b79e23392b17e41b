/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The sink's thread of the streamed renderer
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "band_writer.hpp"

#include <chrono>

namespace sbrt {

BandWriter::BandWriter(const BandSink &sink, size_t buffers)
    : sink_(sink), unallocated_(buffers), thread_([this] { run(); })
{
}

BandWriter::~BandWriter()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void BandWriter::run()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return closing_ || !queued_.empty(); });
        if (queued_.empty())
            return; // closing, nothing left
        Band band = std::move(queued_.front());
        queued_.pop_front();
        busy_ = true;
        if (!error_) {
            lock.unlock();
            const auto start = std::chrono::steady_clock::now();
            try {
                sink_(band);
            }
            catch (...) {
                lock.lock();
                error_ = std::current_exception();
                lock.unlock();
            }
            lock.lock();
            sink_ms_ += std::chrono::duration<double, std::milli>(
                            std::chrono::steady_clock::now() - start)
                            .count();
        }
        busy_ = false;
        free_.push_back(std::move(band));
        changed_.notify_all();
    }
}

void BandWriter::rethrow_locked()
{
    if (error_) {
        std::exception_ptr error = error_;
        error_ = nullptr; // rethrown once; the sink takes no more bands
        queued_.clear();
        closing_ = true;
        changed_.notify_all();
        std::rethrow_exception(error);
    }
}

Band BandWriter::take()
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || !free_.empty() || unallocated_ > 0; });
    rethrow_locked();
    if (!free_.empty()) {
        Band band = std::move(free_.front());
        free_.pop_front();
        return band;
    }
    --unallocated_;
    return Band();
}

void BandWriter::submit(Band band)
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        rethrow_locked();
        queued_.push_back(std::move(band));
    }
    changed_.notify_all();
}

void BandWriter::finish()
{
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return error_ || (queued_.empty() && !busy_); });
    rethrow_locked();
}

} // namespace sbrt
