/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The bands of one image while many threads trace its rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "output/band_flow.hpp"

#include <algorithm>

namespace sbrt {

namespace {

/// `vector` sized for `n` elements (its memory kept from the band's last
/// use), viewed `stride` elements a row; empty where n is 0.
template <typename T, typename Vector>
BandPlane<T> plane_of(Vector &vector, size_t n, size_t stride)
{
    vector.resize(n);
    return n ? BandPlane<T>(vector.data(), stride) : BandPlane<T>();
}

} // namespace

void prepare_band(Band &band, int first_row, int rows, int cols, const Outputs &outputs)
{
    band.first_row = first_row;
    band.rows = rows;
    band.cols = cols;
    const size_t n = band.pixels(), c = size_t(cols);
    Band::Store &store = band.store;
    band.rgb = plane_of<uint8_t>(store.rgb, n * 3, c * 3);
    band.material = plane_of<int32_t>(store.material, outputs.material ? n : 0, c);
    band.elevation = plane_of<double>(store.elevation, outputs.elevation ? n : 0, c);
    band.depth = plane_of<double>(store.depth, outputs.depth ? n : 0, c);
    band.value = plane_of<double>(store.value, outputs.value ? n : 0, c);
}

BandFlow::BandFlow(BandWriter &writer, int rows, int cols, int band_rows,
                   const Outputs &outputs)
    : writer_(writer), rows_(rows), cols_(cols), band_rows_(std::max(1, band_rows)),
      outputs_(outputs), bands_(size_t((rows + band_rows_ - 1) / band_rows_))
{
    rows_left_ = std::make_unique<std::atomic<int>[]>(bands_.size());
    for (size_t b = 0; b < bands_.size(); ++b)
        rows_left_[b].store(std::min(band_rows_, rows - int(b) * band_rows_));
}

Band &BandFlow::band_of(int row)
{
    const int b = row / band_rows_;
    if (b < opened_.load(std::memory_order_acquire))
        return bands_[size_t(b)];
    // in order, one at a time: a thread that needs a later band opens the
    // ones before it, so the sink (which takes bands in order) never waits
    // for a band no buffer was left for; and no lock is held while the
    // writer has no buffer free (the rows of the open bands go on)
    std::unique_lock<std::mutex> lock(open_mutex_);
    while (b >= opened_.load(std::memory_order_relaxed)) {
        if (opening_) {
            opened_changed_.wait(lock);
            continue;
        }
        opening_ = true;
        const int next = opened_.load(std::memory_order_relaxed);
        lock.unlock();
        Band band;
        try {
            band = writer_.take();
        }
        catch (...) {
            lock.lock();
            opening_ = false;
            opened_changed_.notify_all();
            throw;
        }
        const int first = next * band_rows_;
        prepare_band(band, first, std::min(band_rows_, rows_ - first), cols_, outputs_);
        lock.lock();
        bands_[size_t(next)] = std::move(band);
        opened_.store(next + 1, std::memory_order_release);
        opening_ = false;
        opened_changed_.notify_all();
    }
    return bands_[size_t(b)];
}

void BandFlow::row_done(int row)
{
    const int b = row / band_rows_;
    // acq_rel: the last thread sees every other thread's rows of the band
    if (rows_left_[size_t(b)].fetch_sub(1, std::memory_order_acq_rel) == 1)
        writer_.submit(std::move(bands_[size_t(b)]));
}

} // namespace sbrt
