/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The hit records' pass: records of bands of rows, decoded on
 *            the host
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_record_pass.hpp"

#include <algorithm>

#include "gpu_internal.hpp"
#include "tracing/cpu_tracing.hpp"
#include "util/parallel.hpp"

namespace sbrt_gl {

void GpuRecordPass::trace(const sbrt::Camera &camera, sbrt::GpuView &view, int first,
                          int count, sbrt::Hit *out, unsigned cpu_threads)
{
    ensure_band_buffer(passes_.gl, band_, count,
                       size_t(camera.cols()) * sizeof(sbrt::GpuPixelHit),
                       passes_.max_block_bytes);
    records_.resize(size_t(count) * size_t(camera.cols()));
    passes_.programs.get(Pass::records).use();
    dispatch(camera, view, first, count);
    decode(camera, first, count, out, cpu_threads);
}

void GpuRecordPass::dispatch(const sbrt::Camera &camera, sbrt::GpuView &view, int first_row,
                             int row_count)
{
    const GlApi &gl = passes_.gl;
    GpuStats &stats = passes_.stats;
    const int cols = camera.cols();
    const size_t row_bytes = size_t(cols) * sizeof(sbrt::GpuPixelHit);
    int band_rows = int(band_->bytes() / row_bytes);
    if (const int crowded = passes_.crowded_band_rows(cols))
        band_rows = std::min(band_rows, crowded);
    band_->bind(2);
    for (int first = first_row; first < first_row + row_count; first += band_rows) {
        const int count = std::min(band_rows, first_row + row_count - first);
        passes_.upload_view(view, first, count);
        // a paged model: again once the blocks its rays missed are up
        PassContext::BandPaging paging = passes_.begin_band();
        do {
            auto start = Clock::now();
            passes_.dispatch(Pass::records, cols, count);
            gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            gl.Finish();
            check_gl(gl, "the ray casting dispatch");
            stats.trace_ms += ms_since(start);
            start = Clock::now();
            band_->download(records_.data() + size_t(first - first_row) * size_t(cols),
                            size_t(count) * row_bytes);
            stats.readback_ms += ms_since(start);
        } while (passes_.band_again(paging));
        ++stats.bands;
    }
}

void GpuRecordPass::decode(const sbrt::Camera &camera, int first_row, int row_count,
                           sbrt::Hit *out, unsigned cpu_threads)
{
    const sbrt::Tracer &tracer = passes_.tracer;
    const int cols = camera.cols();
    const auto start = Clock::now();
    std::vector<size_t> over_per_row(size_t(row_count), 0);
    sbrt::for_each_row(first_row, first_row + row_count, cpu_threads, [&](int row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row - first_row) * cols + col;
            const sbrt::Ray ray = camera.ray(row, col);
            bool over_budget = false;
            out[i] = sbrt::decode_gpu_hit(tracer, ray, records_[i], over_budget);
            if (over_budget) {
                out[i] = tracer.trace(ray);
                ++over_per_row[size_t(row - first_row)];
            }
        }
    });
    for (size_t n : over_per_row)
        passes_.stats.over_budget += n;
    passes_.stats.readback_ms += ms_since(start);
}

} // namespace sbrt_gl
