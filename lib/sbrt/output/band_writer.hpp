/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Hands finished bands to a sink on a thread of its own, in
 *            order of their rows whatever order they are finished in,
 *            while the next bands are traced; a few band buffers circulate
 *            between the renderer and the sink
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_WRITER_HPP
#define SBRT_BAND_WRITER_HPP

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "output/band.hpp"
#include "util/error.hpp"

namespace sbrt {

/// \brief The sink's thread, kept from frame to frame with the band
/// buffers (their memory warm). Only that thread calls the sink, so a sink
/// that is not thread-safe (GRASS's raster library) is safe as long as
/// nothing else calls it meanwhile. Per frame (start() to end_frame()) the
/// sink takes the bands in the order of their rows from row 0: a band
/// submitted early waits for the bands above it. An exception of the sink
/// is rethrown by every later take(), submit() or finish() of that frame on
/// the renderer's side (any of its threads).
class BandWriter {
public:
    BandWriter(); ///< idle until start()
    /// start(sink, buffers) at once (a writer for one frame).
    explicit BandWriter(const BandSink &sink, size_t buffers = 2);
    ~BandWriter(); ///< waits for the sink's thread (after finish: at once)
    BandWriter(const BandWriter &) = delete;
    BandWriter &operator=(const BandWriter &) = delete;

    /// A frame whose bands go to `sink` (which must outlive end_frame()),
    /// at most `buffers` of them out at once (taken and not yet sunk).
    void start(const BandSink &sink, size_t buffers);
    /// A band buffer to fill (waits while `buffers` are out).
    Band take();
    /// Queues a filled band for the sink (thread-safe).
    void submit(Band band);
    /// Waits until the sink took every band; rethrows its exception.
    void finish();
    /// Gives up (a renderer thread failed): take() waiting or called later
    /// throws Cancelled rather than wait for bands that will never come.
    void cancel();
    /// Ends the frame however it went: bands not yet sunk are dropped and
    /// the sink is not called again (waits while it runs).
    void end_frame();

    /// What take() throws after cancel(): not the render's error (the
    /// thread that cancelled has that one), so threads drop it.
    struct Cancelled : Error {
        Cancelled() : Error("band writer: cancelled (a renderer thread failed)") {}
    };
    /// Time the renderer's threads waited in take() for a buffer the
    /// sink still held (ms, all threads together; this frame).
    double take_wait_ms() const { return take_wait_ms_; }
    /// Time the sink took so far (ms, this frame; read after finish()).
    double sink_ms() const { return sink_ms_; }

private:
    void run();
    void rethrow_locked();
    /// The queued band that comes next, or queued_.end().
    std::deque<Band>::iterator next_band();

    const BandSink *sink_ = nullptr; ///< this frame's
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Band> queued_, free_;
    size_t buffers_ = 0, out_ = 0; ///< this frame's limit; bands out
    bool closing_ = false, busy_ = false, cancelled_ = false;
    int next_row_ = 0; ///< the first row of the band the sink takes next
    double sink_ms_ = 0, take_wait_ms_ = 0;
    std::exception_ptr error_;
    std::thread thread_;
};

/// \brief Ends a frame of `writer` (end_frame) when the scope is left, by
/// return or exception: the sink is never called after the render that
/// gave it returns.
class BandFrame {
public:
    BandFrame(BandWriter &writer, const BandSink &sink, size_t buffers) : writer_(writer)
    {
        writer_.start(sink, buffers);
    }
    ~BandFrame() { writer_.end_frame(); }
    BandFrame(const BandFrame &) = delete;
    BandFrame &operator=(const BandFrame &) = delete;

private:
    BandWriter &writer_;
};

} // namespace sbrt

#endif
