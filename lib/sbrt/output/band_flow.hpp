/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The bands of one image while many threads trace and shade
 *            its rows in any order: no thread waits for the others at the
 *            end of a band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_FLOW_HPP
#define SBRT_BAND_FLOW_HPP

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include "output/band.hpp"
#include "output/band_writer.hpp"

namespace sbrt {

/// Sizes the band's vectors for `rows` rows of the outputs asked for.
void prepare_band(Band &band, int first_row, int rows, int cols, const Outputs &outputs);

/// \brief Rows go to the threads in order, a run of them at a time
/// (WorkerPool::for_each_take); each row is written into its band, and a
/// band goes to the writer when its last row is done, whichever thread
/// does it. Bands are opened in
/// order, each with a buffer from the writer (waiting while the sink holds
/// them all): the threads run at most the writer's buffers ahead of the
/// sink, and never wait for each other at a band's end.
class BandFlow {
public:
    BandFlow(BandWriter &writer, int rows, int cols, int band_rows, const Outputs &outputs);
    BandFlow(const BandFlow &) = delete;
    BandFlow &operator=(const BandFlow &) = delete;

    /// The band that holds `row`, opened (with every band before it) if
    /// it is not yet (thread-safe).
    Band &band_of(int row);
    /// `row` is written; its band goes to the writer once all its rows
    /// are (thread-safe).
    void row_done(int row);
    /// A thread failed: the threads waiting to open a band stop waiting.
    void abort() { writer_.cancel(); }
    int bands() const { return int(bands_.size()); }

private:
    BandWriter &writer_;
    int rows_, cols_, band_rows_;
    Outputs outputs_;
    std::vector<Band> bands_;
    std::unique_ptr<std::atomic<int>[]> rows_left_; ///< per band
    std::atomic<int> opened_{0};                     ///< bands [0, opened_) are open
    std::mutex open_mutex_;
    std::condition_variable opened_changed_;
    bool opening_ = false; ///< a thread is opening band opened_
};

} // namespace sbrt

#endif
