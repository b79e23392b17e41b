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

BandWriter::BandWriter(const BandSink &sink, size_t buffers, std::vector<Band> spare)
    : sink_(sink), unallocated_(buffers)
{
    while (!spare.empty() && free_.size() < buffers) {
        free_.push_back(std::move(spare.back()));
        spare.pop_back();
    }
    unallocated_ -= free_.size();
    thread_ = std::thread([this] { run(); });
}

std::vector<Band> BandWriter::release_bands()
{
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Band> bands;
    for (Band &band : free_)
        bands.push_back(std::move(band));
    free_.clear();
    return bands;
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
        // the sink takes no more bands; every later call rethrows
        queued_.clear();
        closing_ = true;
        changed_.notify_all();
        std::rethrow_exception(error_);
    }
}

Band BandWriter::take()
{
    std::unique_lock<std::mutex> lock(mutex_);
    const auto ready = [&] {
        return error_ || cancelled_ || !free_.empty() || unallocated_ > 0;
    };
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

void BandWriter::cancel()
{
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        cancelled_ = true;
    }
    changed_.notify_all();
}

} // namespace sbrt
