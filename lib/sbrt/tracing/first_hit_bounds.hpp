/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The coarse first pass: per tile of pixels, a conservative
 *            lower bound of where its rays may first meet what the tracer
 *            draws, from the tracer's min-max pyramid, so that each ray's
 *            walk starts there rather than at the model's box
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FIRST_HIT_BOUNDS_HPP
#define SBRT_FIRST_HIT_BOUNDS_HPP

#include <cmath>
#include <cstdint>
#include <vector>

#include "scene/camera.hpp"
#include "tracing/tracer.hpp"
#include "util/worker_pool.hpp"

namespace sbrt {

/// \brief The rays of a tile of pixels form a beam whose cross-section,
/// per axis of the local frame, grows linearly with the ray parameter.
/// Its nodes searched nearest first (a best-first search over the
/// pyramid), the first cell whose box (with its z-range) the beam enters
/// bounds every ray of the tile: no ray meets anything before it. After
/// `budget` nodes the nearest node not yet opened gives the bound.
class FirstHitBounds {
public:
    /// Without a pyramid (skipping off, the model not drawn) every bound is 0.
    FirstHitBounds(const Tracer &tracer, const Camera &camera, int tile,
                   int budget, unsigned threads = 0);
    /// No first pass: every bound is 0.
    explicit FirstHitBounds(const Camera &camera) : camera_(camera), tile_(1), budget_(1) {}
    /// The same on `pool`'s workers.
    FirstHitBounds(const Tracer &tracer, const Camera &camera, int tile, int budget,
                   WorkerPool &pool);
    /// A t (of the unit ray of pixel (row, col), `ray` = camera.ray(row,
    /// col)) before which the ray meets nothing; inf where it meets nothing.
    double t_start(int row, int col, const Ray &ray) const;
    /// Whether the ray of pixel (row, col) surely meets nothing (its
    /// tile's beam misses everything): its hit is Hit(), its ray need not
    /// even be made.
    bool meets_nothing(int row, int col) const
    {
        return !s_bounds_.empty() && s_bound(row, col) == INFINITY;
    }

    /// Tiles, and those whose rays all meet nothing (reports and tests).
    size_t tiles() const { return s_bounds_.size(); }
    size_t empty_tiles() const;

private:
    /// The bound of one tile in the parameter s of the unnormalised ray
    /// direction D (t = s |D|).
    double tile_bound(const Tracer &tracer, int row0, int col0) const;
    /// The arrays of the bounds of `tracer`'s pyramid; false without one.
    bool allocate(const Tracer &tracer);
    /// Tiles are found in runs of TILE_RUN, row-major: tens of
    /// microseconds each, many more than threads, and few enough that
    /// taking one from the threads' shared counter costs nothing beside it.
    static constexpr size_t TILE_RUN = 16;
    int tile_runs() const;
    /// The bounds of run `run`'s tiles.
    void find_run(const Tracer &tracer, int run);
    /// The bound of the tile of pixel (row, col), in s.
    double s_bound(int row, int col) const
    {
        return s_bounds_[size_t(row_offset_[size_t(row)]) + col_tile_[size_t(col)]];
    }

    const Camera &camera_;
    int tile_, budget_, tile_cols_ = 0;
    std::vector<double> s_bounds_; ///< per tile, row-major
    /// Per image row, its tile row's first bound; per column, its tile
    /// column (no division per pixel).
    std::vector<uint32_t> row_offset_, col_tile_;
};

} // namespace sbrt

#endif
