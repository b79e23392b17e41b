/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   First hits of the rows of an image with the exact tracer on
 *            all cores (backend=cpu, and the reference of the GPU path)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CPU_TRACING_HPP
#define SBRT_CPU_TRACING_HPP

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "output/band.hpp"
#include "tracing/first_hit_bounds.hpp"
#include "tracing/hit_image.hpp"
#include "util/worker_pool.hpp"

namespace sbrt {

/// Columns a thread traces down its take of rows before it moves right:
/// the rays of a block of 8 rows by 64 columns cross fewer cells than 8
/// whole rows, so more of them are still in the thread's cache.
constexpr int COLS_PER_BLOCK = 64;

/// Calls span_function(row, c0, c1) over rows [first, end) and columns
/// [0, cols) in blocks of COLS_PER_BLOCK columns: the first block of
/// every row, top to bottom, then the next block.
template <typename SpanFunction>
void for_each_block(int first, int end, int cols, const SpanFunction &span_function)
{
    for (int c0 = 0; c0 < cols; c0 += COLS_PER_BLOCK) {
        const int c1 = std::min(cols, c0 + COLS_PER_BLOCK);
        for (int row = first; row < end; ++row)
            span_function(row, c0, c1);
    }
}

/// Tile side (pixels) and node budget of the coarse first pass. Measured on
/// models A to C at 1056 x 884: tiles of 4 pixels cost more than they save;
/// 8 and 16, with budgets of 16 to 64, are within noise.
constexpr int FIRST_PASS_TILE = 8, FIRST_PASS_BUDGET = 32;

/// What the coarse first pass did: its tiles, those whose rays all meet
/// nothing (not walked at all), its time.
struct FirstPassReport {
    size_t tiles = 0, empty_tiles = 0;
    double ms = 0;
};

/// A rectangle of an image's pixels: first row, last row, first column,
/// last column (inclusive).
using PixelRect = std::array<int, 4>;

/// The corners of `box` (low, high) in front of `camera`, in normalised
/// device coordinates; `behind` counts the others (a perspective camera's).
std::vector<glm::dvec2> projected_corners(const std::array<glm::dvec3, 2> &box,
                                          const Camera &camera, int &behind);

/// The rectangles of `camera`'s pixels whose rays may meet one of `boxes`
/// (low and high corners, exaggerated map coordinates): their projections,
/// a pixel of margin (boxes wholly behind a perspective camera: none);
/// none at all where a box reaches behind the camera (every pixel may).
std::optional<std::vector<PixelRect>> pixel_rects_of(
    const std::vector<std::array<glm::dvec3, 2>> &boxes, const Camera &camera);

/// The column spans [first, last] of `row` within any of `rects`, in
/// order, overlapping or touching spans merged.
std::vector<std::pair<int, int>> row_spans(const std::vector<PixelRect> &rects, int row);

/// \brief Whatever traces the rows of one camera's image: the CPU tracer
/// below, or a GPU (lib/sbrt_gl). The streamed renderer asks it for bands
/// of rows, in any order, each row possibly more than once (the same hits).
class RowTracer {
public:
    virtual ~RowTracer() = default;
    /// Hits of rows [first, first + count), row-major, into `out`.
    virtual void trace_rows(int first, int count, Hit *out) = 0;
    /// Rows per band this tracer works best with for an image `cols`
    /// wide; 0: the renderer's choice.
    virtual int preferred_band_rows(int /*cols*/) const { return 0; }
    /// The most rows a band `cols` wide of `outputs` may have (what
    /// shade_rows holds at once); the renderer's band_rows never exceed it.
    virtual int max_band_rows(int /*cols*/, const Outputs & /*outputs*/) const
    {
        return INT32_MAX;
    }
    /// Bands the renderer's sink holds at most besides the one being
    /// filled: a tracer that shades into memory of its own (a GPU's mapped
    /// buffers) has that many more bands' room.
    static constexpr size_t SINK_BANDS = 2;
    /// Where the tracer shades too (a GPU): the band's outputs of those
    /// rows, into the band's own store (prepare_band) or memory the band
    /// then views (its planes set); false where it does not, the band
    /// left as it was.
    virtual bool shade_rows(int /*first*/, int /*count*/, const Outputs & /*outputs*/,
                            Band & /*band*/)
    {
        return false;
    }
    /// Whether shade_rows also finds the image-space kernel normals (the
    /// renderer then keeps no window of hits of its own).
    virtual bool shades_kernel_normals() const { return false; }
};

/// \brief The exact CPU tracer over the rows of `camera`, on `threads`
/// threads (0: all cores). With `first_pass` (and the tracer's pyramid)
/// each ray starts where the coarse first pass (FirstHitBounds) puts its
/// tile's first possible hit, found at construction on `pool`'s workers
/// where given, else on `threads` threads. Holds references to both
/// arguments.
class CpuRowTracer : public RowTracer {
public:
    CpuRowTracer(const Tracer &tracer, const Camera &camera, unsigned threads = 0,
                 bool first_pass = true, WorkerPool *pool = nullptr);
    /// Rows [first, first + count) into `out` (row-major), takes of up to
    /// ROWS_PER_TAKE rows each traced block by block (for_each_block).
    void trace_rows(int first, int count, Hit *out) override;
    /// The hits of columns [c0, c1) of one row into out[c0 .. c1)
    /// (thread-safe).
    void trace_span(int row, int c0, int c1, Hit *out) const;
    /// The hits of one row (thread-safe).
    void trace_row(int row, Hit *out) const { trace_span(row, 0, camera_.cols(), out); }
    const FirstPassReport &first_pass() const { return report_; }

private:
    /// Where the tracer draws only overlays: per row, the columns (first,
    /// last; merged) of the pixel rectangles outside which no ray can hit
    /// anything; none where every pixel is traced.
    std::optional<std::vector<std::vector<std::pair<int, int>>>> overlay_spans_;
    const Tracer &tracer_;
    const Camera &camera_;
    unsigned threads_;
    FirstPassReport report_;
    std::optional<FirstHitBounds> bounds_;
};

/// Hits of camera.ray(r, c), row-major, for the whole image (tests,
/// benchmarks and the reference; the module streams bands through
/// Renderer); `threads` 0 means all cores.
HitImage trace_image(const Tracer &tracer, const Camera &camera,
                     unsigned threads = 0, bool first_pass = true,
                     FirstPassReport *report = nullptr);

} // namespace sbrt

#endif
