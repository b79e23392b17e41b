/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Hands finished bands to a sink on a thread of its own, in
 *            order, while the next bands are traced; two band buffers
 *            circulate between the renderer and the sink
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_WRITER_HPP
#define SBRT_BAND_WRITER_HPP

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "band.hpp"

namespace sbrt {

/// \brief The sink's thread. Only that thread calls the sink, so a sink
/// that is not thread-safe (GRASS's raster library) is safe as long as
/// nothing else calls it meanwhile. An exception of the sink is rethrown
/// by the next take(), submit() or finish() on the renderer's side.
class BandWriter {
public:
    explicit BandWriter(const BandSink &sink, size_t buffers = 2);
    ~BandWriter(); ///< waits for the sink's thread (after finish: at once)
    BandWriter(const BandWriter &) = delete;
    BandWriter &operator=(const BandWriter &) = delete;

    /// A band buffer to fill (waits while the sink holds all of them).
    Band take();
    /// Queues a filled band for the sink.
    void submit(Band band);
    /// Waits until the sink took every band; rethrows its exception.
    void finish();
    /// Time the sink took so far (ms; read after finish()).
    double sink_ms() const { return sink_ms_; }

private:
    void run();
    void rethrow_locked();

    const BandSink &sink_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Band> queued_, free_;
    size_t unallocated_;
    bool closing_ = false, busy_ = false;
    double sink_ms_ = 0;
    std::exception_ptr error_;
    std::thread thread_;
};

} // namespace sbrt

#endif
