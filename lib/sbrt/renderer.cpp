/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The streamed render pipeline
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/geometric.hpp>

#include "output/band_flow.hpp"
#include "output/band_writer.hpp"
#include "util/error.hpp"
#include "shading/hit_window.hpp"
#include "shading/kernel_normals.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// \brief Shades rows of hits into a band: the colour and the outputs asked
/// for.
struct RowShader {
    const Tracer &tracer;
    const PixelShader &shader;
    const Camera &camera;

    /// Columns [c0, c1) of `row`.
    void operator()(const Hit *hits, int row, Band &band, int c0, int c1) const
    {
        for (int col = c0; col < c1; ++col)
            shade_into_band(tracer, shader, camera, hits[col], row, col, band);
    }
    void operator()(const Hit *hits, int row, Band &band) const
    {
        (*this)(hits, row, band, 0, band.cols);
    }
};

/// \brief Kernel normals (and their smoothing) band by band over a window
/// of traced rows: a band's pixels read the depths of the rows their
/// kernel cells project to, and smoothing reads the kernel normals of
/// `radius` rows on either side.
class KernelBands {
public:
    KernelBands(const Tracer &tracer, const Camera &camera, const Shading &shading,
                RowTracer &rows, unsigned threads)
        : kernel_(tracer, camera, shading.kernel), window_(rows, camera.cols()),
          rows_(camera.rows()), cols_(camera.cols()), threads_(threads)
    {
        if (shading.smooth > 0)
            weight_ = gaussian_weights(shading.smooth);
        radius_ = weight_.empty() ? 0 : int(weight_.size() / 2);
    }

    /// Rows [first, last) with their final normals, in the window.
    void prepare(int first, int last)
    {
        const int lo = std::max(0, first - radius_), hi = std::min(rows_, last + radius_);
        window_.drop_before(std::min(lo, lowest_reach_from(lo)));
        window_.cover(lo, hi);
        add_depths(lo, hi);
        // the rows the kernel reads for rows [lo, hi)
        for_each_row(lo, hi, threads_, [&](int r) {
            HitWindow::Row &row = window_.row(r);
            if (row.reach.first < 0)
                row.reach = kernel_.row_reach(row.hits.data());
        });
        int need_lo = lo, need_hi = hi;
        for (int r = lo; r < hi; ++r) {
            const auto reach = window_.row(r).reach;
            if (reach.first < reach.second) {
                need_lo = std::min(need_lo, reach.first);
                need_hi = std::max(need_hi, reach.second);
                reach_above_ = std::max(reach_above_, r - reach.first);
            }
        }
        window_.cover(need_lo, need_hi);
        add_depths(need_lo, need_hi);
        apply_kernel(lo, hi);
        if (radius_)
            smooth(first, last, lo, hi);
    }

    const Hit *hits(int row) { return window_.row(row).hits.data(); }
    int most_rows() const { return window_.most_rows(); }

private:
    /// The lowest row a later band may read, as far as the bands so far
    /// tell (rows dropped too early are traced again: the same hits).
    int lowest_reach_from(int row) const { return row - reach_above_; }

    void add_depths(int first, int last)
    {
        for_each_row(first, last, threads_, [&](int r) {
            HitWindow::Row &row = window_.row(r);
            if (!row.depth.empty())
                return;
            row.depth.resize(size_t(cols_));
            for (int c = 0; c < cols_; ++c)
                row.depth[size_t(c)] = kernel_.view_depth(row.hits[size_t(c)]);
        });
    }

    void apply_kernel(int first, int last)
    {
        // the window's depth rows, for lookups without the deque
        const int base = window_.first();
        std::vector<const double *> depth_rows;
        for (int r = base; r < window_.last(); ++r)
            depth_rows.push_back(window_.row(r).depth.data());
        const auto depth_at = [&](int r, int c) {
            return depth_rows[size_t(r - base)][c];
        };
        for_each_row(first, last, threads_, [&](int r) {
            HitWindow::Row &row = window_.row(r);
            if (row.kernel_done)
                return;
            for (int c = 0; c < cols_; ++c) {
                Hit &hit = row.hits[size_t(c)];
                if (hit.is_hit())
                    kernel_.normal(hit, row.depth[size_t(c)], depth_at, hit.normal);
            }
            row.kernel_done = true;
        });
    }

    /// Gaussian smoothing as smooth_normals does it: along each row of
    /// [lo, hi), then down the columns of [first, last).
    void smooth(int first, int last, int lo, int hi)
    {
        for_each_row(lo, hi, threads_, [&](int r) {
            HitWindow::Row &row = window_.row(r);
            if (!row.across.empty())
                return;
            row.across.assign(size_t(cols_), glm::dvec3(0));
            for (int c = 0; c < cols_; ++c) {
                if (!row.hits[size_t(c)].is_hit())
                    continue;
                glm::dvec3 sum(0);
                for (int d = -radius_; d <= radius_; ++d) {
                    const int cc = c + d;
                    if (cc >= 0 && cc < cols_ && row.hits[size_t(cc)].is_hit())
                        sum += weight_[size_t(d + radius_)] *
                               glm::dvec3(row.hits[size_t(cc)].normal);
                }
                row.across[size_t(c)] = sum;
            }
        });
        // every row of [lo, hi) has its first pass before any normal of
        // [first, last) changes
        for_each_row(first, last, threads_, [&](int r) {
            std::vector<glm::dvec3> down(size_t(cols_), glm::dvec3(0));
            HitWindow::Row &row = window_.row(r);
            for (int c = 0; c < cols_; ++c) {
                if (!row.hits[size_t(c)].is_hit())
                    continue;
                for (int d = -radius_; d <= radius_; ++d) {
                    const int rr = r + d;
                    if (rr < 0 || rr >= rows_)
                        continue;
                    HitWindow::Row &other = window_.row(rr);
                    if (other.hits[size_t(c)].is_hit())
                        down[size_t(c)] += weight_[size_t(d + radius_)] * other.across[size_t(c)];
                }
            }
            for (int c = 0; c < cols_; ++c) {
                const double length = glm::length(down[size_t(c)]);
                if (row.hits[size_t(c)].is_hit() && length > 0)
                    row.hits[size_t(c)].normal = down[size_t(c)] / length;
            }
        });
    }

    KernelNormals kernel_;
    HitWindow window_;
    int rows_, cols_;
    unsigned threads_;
    std::vector<double> weight_;
    int radius_ = 0;
    int reach_above_ = 0;
};

/// Milliseconds since `start`.
double ms_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                     start)
        .count();
}

/// The CPU tracer with face normals, in one pass over the image's rows:
/// a thread takes a run of rows and traces and shades it block by block
/// (for_each_block: a block's hits stay in cache, and the cells its rays
/// cross), runs are taken in order by any thread, and a band goes to the
/// sink when its last row is done (no thread waits for the others at a
/// band's end).
void render_rows(const CpuRowTracer &cpu, const RowShader &shade, const Outputs &outputs,
                 const BandSink &sink, WorkerPool &pool, BandWriter &writer, int rows,
                 int cols, RenderReport &report)
{
    const unsigned threads = pool.size();
    // each thread a run of consecutive rows at a time (its cache holds the
    // cells the run's rays cross). A thread opens the bands of its whole
    // run before it traces a row of it, so a run must never span more
    // bands than the writer has buffers (it would wait for its own rows):
    // a run of ROWS_PER_TAKE rows spans at most 7 / band_rows + 2 bands,
    // fewer than these buffers, which keep every thread's run going
    const BandFrame frame(writer, sink,
                          std::max<size_t>(3, 2 * threads * size_t(ROWS_PER_TAKE) /
                                                      size_t(report.band_rows) +
                                                  2));
    BandFlow flow(writer, rows, cols, report.band_rows, outputs);
    std::vector<double> busy(threads, 0.0);
    const auto start = std::chrono::steady_clock::now();
    pool.for_each_take(0, rows, [&](int first, int end, unsigned worker) {
        try {
            thread_local HitImage hits; // warm from frame to frame
            thread_local std::vector<Band *> bands;
            hits.resize(size_t(end - first) * size_t(cols));
            bands.clear();
            for (int row = first; row < end; ++row)
                bands.push_back(&flow.band_of(row));
            const auto take_start = std::chrono::steady_clock::now();
            for_each_block(first, end, cols, [&](int row, int c0, int c1) {
                Hit *row_hits = hits.data() + size_t(row - first) * size_t(cols);
                cpu.trace_span(row, c0, c1, row_hits);
                shade(row_hits, row, *bands[size_t(row - first)], c0, c1);
            });
            busy[worker] += ms_since(take_start);
            for (int row = first; row < end; ++row)
                flow.row_done(row);
        }
        catch (const BandWriter::Cancelled &) {
            // another thread failed and cancelled: its error is the one
            // the caller gets
        }
        catch (...) {
            flow.abort(); // no thread waits for a band that cannot come
            throw;
        }
    }, ROWS_PER_TAKE);
    report.trace_ms = ms_since(start);
    writer.finish();
    report.bands = flow.bands();
    report.sink_ms = writer.sink_ms();
    report.band_wait_ms = writer.take_wait_ms();
    report.worker_busy_ms.resize(threads, 0.0); // the first pass's, then the rows'
    for (unsigned w = 0; w < threads; ++w)
        report.worker_busy_ms[w] += busy[w];
    report.most_rows_held = int(threads) * ROWS_PER_TAKE; // a take of hits per thread
}

/// Band by band: kernel normals (over their window of rows, when given),
/// or another RowTracer (a GPU), which may shade its bands itself.
void render_bands(RowTracer &source, KernelBands *kernel, const RowShader &shade,
                  const Outputs &outputs, const BandSink &sink, unsigned threads,
                  BandWriter &writer, int rows, int cols, RenderReport &report)
{
    HitImage band_hits; // made when a band is first traced on this side
    bool shaded_by_tracer = false;
    const BandFrame frame(writer, sink, RowTracer::SINK_BANDS);
    for (int first = 0; first < rows; first += report.band_rows) {
        const int count = std::min(report.band_rows, rows - first);
        Band band = writer.take();
        const auto start = std::chrono::steady_clock::now();
        if (kernel) {
            prepare_band(band, first, count, cols, outputs);
            kernel->prepare(first, first + count);
            for_each_row(first, first + count, threads,
                         [&](int row) { shade(kernel->hits(row), row, band); });
        }
        else if (source.shade_rows(first, count, outputs, band)) {
            shaded_by_tracer = true; // no hits on this side
        }
        else {
            prepare_band(band, first, count, cols, outputs);
            if (band_hits.empty())
                band_hits = HitImage(size_t(report.band_rows) * cols);
            source.trace_rows(first, count, band_hits.data());
            for_each_row(first, first + count, threads, [&](int row) {
                shade(band_hits.data() + size_t(row - first) * cols, row, band);
            });
        }
        report.trace_ms += ms_since(start);
        writer.submit(std::move(band));
        ++report.bands;
    }
    writer.finish();
    report.sink_ms = writer.sink_ms();
    report.band_wait_ms = writer.take_wait_ms();
    report.most_rows_held = kernel             ? kernel->most_rows()
                            : shaded_by_tracer ? 0
                                               : report.band_rows;
}

} // namespace

Renderer::Renderer(Model model, double zexag, Scene scene, Shading shading,
                   RenderSettings settings)
    : model_(std::make_unique<const Model>(std::move(model))),
      tracer_(std::make_unique<const Tracer>(*model_, zexag, std::move(scene))),
      shading_(shading), settings_(settings)
{
}

RenderReport Renderer::render(const Camera &camera, const Outputs &outputs,
                              const BandSink &sink, RowTracer *rows) const
{
    const auto start = std::chrono::steady_clock::now();
    // a window (a tile of a larger image) renders its own pixels of the
    // larger image; kernel normals refuse one (KernelNormals)
    const unsigned threads = thread_count(settings_.threads);
    const int image_rows = camera.rows(), cols = camera.cols();
    RenderReport report;
    // enough rows per band that every thread takes several (dynamic
    // scheduling evens out rows of different cost)
    const int preferred = rows ? rows->preferred_band_rows(cols) : 0;
    report.band_rows = std::min(image_rows, settings_.band_rows > 0 ? settings_.band_rows
                                            : preferred > 0        ? preferred
                                                                   : std::max(16, 4 * int(threads)));
    if (rows)
        report.band_rows = std::max(1, std::min(report.band_rows, rows->max_band_rows(cols, outputs)));
    // the threads and band buffers of the frames before: renders take turns
    const std::lock_guard<std::mutex> frame(frame_mutex_);
    if (!writer_)
        writer_ = std::make_unique<BandWriter>();
    std::optional<CpuRowTracer> cpu;
    if (!rows) {
        if (!pool_ || pool_->size() != threads)
            pool_ = std::make_unique<WorkerPool>(threads);
        cpu.emplace(*tracer_, camera, threads, settings_.first_pass, pool_.get());
        report.first_pass = cpu->first_pass();
        if (report.first_pass.tiles)
            report.worker_busy_ms = pool_->busy_ms();
    }
    RowTracer &source = rows ? *rows : *cpu;
    if (!shader_)
        shader_ = std::make_unique<KeptPixelShader>(*model_);
    const RowShader shade{*tracer_, shader_->of(shading_), camera};
    std::optional<KernelBands> kernel;
    if (shading_.normals == Normals::kernel && !(rows && rows->shades_kernel_normals()))
        kernel.emplace(*tracer_, camera, shading_, source, threads);
    if (cpu && !kernel) {
        render_rows(*cpu, shade, outputs, sink, *pool_, *writer_, camera.rows(), cols, report);
    }
    else {
        render_bands(source, kernel ? &*kernel : nullptr, shade, outputs, sink, threads,
                     *writer_, camera.rows(), cols, report);
    }
    report.ms = ms_since(start);
    return report;
}

Image empty_image(const Camera &camera, const Outputs &outputs)
{
    Image image;
    image.rows = camera.rows();
    image.cols = camera.cols();
    const size_t pixels = size_t(image.rows) * image.cols;
    image.rgb.resize(pixels * 3);
    image.material.assign(outputs.material ? pixels : 0, NULL_CLASS);
    image.elevation.assign(outputs.elevation ? pixels : 0, NAN);
    image.depth.assign(outputs.depth ? pixels : 0, NAN);
    image.value.assign(outputs.value ? pixels : 0, NAN);
    return image;
}

namespace {

/// The rows of `plane` into `image`'s vector from the band's first pixel,
/// `per_pixel` elements a pixel.
template <typename T, typename Vector>
void gather_plane(const Band &band, const BandPlane<T> &plane, size_t per_pixel, Vector &image)
{
    if (plane.empty())
        return;
    const size_t row_elements = size_t(band.cols) * per_pixel;
    for (int r = 0; r < band.rows; ++r)
        std::copy_n(plane.row(r), row_elements,
                    image.begin() + ptrdiff_t(size_t(band.first_row + r) * row_elements));
}

} // namespace

void gather_band(const Band &band, Image &image)
{
    gather_plane(band, band.rgb, 3, image.rgb);
    gather_plane(band, band.material, 1, image.material);
    gather_plane(band, band.elevation, 1, image.elevation);
    gather_plane(band, band.depth, 1, image.depth);
    gather_plane(band, band.value, 1, image.value);
}

Image Renderer::render_image(const Camera &camera, const Outputs &outputs,
                             RowTracer *rows) const
{
    Image image = empty_image(camera, outputs);
    render(camera, outputs, [&](const Band &band) { gather_band(band, image); }, rows);
    return image;
}

} // namespace sbrt
