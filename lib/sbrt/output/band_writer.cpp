/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The sink's thread of the streamed renderer
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "output/band_writer.hpp"

#include <algorithm>
#include <chrono>

#include "util/error.hpp"

namespace sbrt {

BandWriter::BandWriter() : thread_([this] { run(); }) {}

BandWriter::BandWriter(const BandSink &sink, size_t buffers) : BandWriter()
{
    start(sink, buffers);
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

void BandWriter::start(const BandSink &sink, size_t buffers)
{
    const std::lock_guard<std::mutex> lock(mutex_);
    sink_ = &sink;
    buffers_ = std::max<size_t>(buffers, 1);
    out_ = 0;
    next_row_ = 0;
    cancelled_ = false;
    error_ = nullptr;
    sink_ms_ = take_wait_ms_ = 0;
    for (Band &band : queued_)
        free_.push_back(std::move(band));
    queued_.clear();
}

void BandWriter::end_frame()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (Band &band : queued_)
        free_.push_back(std::move(band));
    queued_.clear();
    changed_.wait(lock, [&] { return !busy_; });
    sink_ = nullptr;
}

std::deque<Band>::iterator BandWriter::next_band()
{
    return std::find_if(queued_.begin(), queued_.end(),
                        [&](const Band &band) { return band.first_row == next_row_; });
}

void BandWriter::run()
{
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return closing_ || next_band() != queued_.end(); });
        const auto next = next_band();
        if (next == queued_.end())
            return; // closing, nothing left to take in order
        Band band = std::move(*next);
        queued_.erase(next);
        next_row_ += band.rows;
        busy_ = true;
        if (!error_ && sink_) {
            const BandSink &sink = *sink_;
            lock.unlock();
            const auto start = std::chrono::steady_clock::now();
            std::exception_ptr error;
            try {
                sink(band);
            }
            catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            if (error && !error_)
                error_ = error;
            sink_ms_ += std::chrono::duration<double, std::milli>(
                            std::chrono::steady_clock::now() - start)
                            .count();
        }
        busy_ = false;
        free_.push_back(std::move(band));
        if (out_ > 0)
            --out_;
        changed_.notify_all();
    }
}

void BandWriter::rethrow_locked()
{
    if (error_) {
        // the sink takes no more bands of this frame; every later call
        // rethrows
        for (Band &band : queued_)
            free_.push_back(std::move(band));
        queued_.clear();
        changed_.notify_all();
        std::rethrow_exception(error_);
    }
}

Band BandWriter::take()
{
    std::unique_lock<std::mutex> lock(mutex_);
    const auto ready = [&] { return error_ || cancelled_ || out_ < buffers_; };
    if (!ready()) {
        const auto start = std::chrono::steady_clock::now();
        changed_.wait(lock, ready);
        take_wait_ms_ += std::chrono::duration<double, std::milli>(
                             std::chrono::steady_clock::now() - start)
                             .count();
    }
    rethrow_locked();
    if (cancelled_)
        throw Cancelled();
    ++out_;
    if (!free_.empty()) {
        Band band = std::move(free_.front());
        free_.pop_front();
        return band;
    }
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

void BandWriter::cancel()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        cancelled_ = true;
    }
    changed_.notify_all();
}

} // namespace sbrt
