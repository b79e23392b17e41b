/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The coarse first pass (beam against the min-max pyramid)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/first_hit_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include <glm/geometric.hpp>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();
/// Each bound is pulled back by this fraction (and a tiny absolute
/// amount), far beyond the rounding of the beam's corners.
constexpr double MARGIN = 1e-7;

/// The points of a tile's rays at parameter s >= 0 lie, along each local
/// axis, within [o_low + s d_low, o_high + s d_high].
struct Beam {
    glm::dvec3 o_low{INF}, o_high{-INF}, d_low{INF}, d_high{-INF};

    void add(glm::dvec3 o, glm::dvec3 d)
    {
        o_low = glm::min(o_low, o);
        o_high = glm::max(o_high, o);
        d_low = glm::min(d_low, d);
        d_high = glm::max(d_high, d);
    }

    /// The first s >= 0 at which the beam may be in the box [low, high];
    /// inf where it never is.
    double enters(glm::dvec3 low, glm::dvec3 high) const
    {
        double s0 = 0, s1 = INF;
        for (int a = 0; a < 3; ++a) {
            // o_low + s d_low <= high  and  o_high + s d_high >= low
            if (!half_line(o_low[a], d_low[a], high[a], true, s0, s1) ||
                !half_line(o_high[a], d_high[a], low[a], false, s0, s1))
                return INF;
        }
        return s0 <= s1 ? s0 : INF;
    }

private:
    /// Narrows [s0, s1] to where o + s d <= c (below) or >= c (not below).
    static bool half_line(double o, double d, double c, bool below, double &s0,
                          double &s1)
    {
        if (d == 0)
            return below ? o <= c : o >= c;
        const double s = (c - o) / d;
        if ((d > 0) == below)
            s1 = std::min(s1, s);
        else
            s0 = std::max(s0, s);
        return s0 <= s1;
    }
};

/// A pyramid node on the search's frontier.
struct Node {
    double s;
    int level, x, y;
    bool operator>(const Node &other) const { return s > other.s; }
};

} // namespace

FirstHitBounds::FirstHitBounds(const Tracer &tracer, const Camera &camera, int tile,
                               int budget, unsigned threads)
    : camera_(camera), tile_(std::max(1, tile)), budget_(std::max(1, budget))
{
    if (allocate(tracer))
        for_each_row(tile_runs(), threads, [&](int r) { find_run(tracer, r); });
}

FirstHitBounds::FirstHitBounds(const Tracer &tracer, const Camera &camera, int tile,
                               int budget, WorkerPool &pool)
    : camera_(camera), tile_(std::max(1, tile)), budget_(std::max(1, budget))
{
    if (allocate(tracer))
        pool.for_each_row(0, tile_runs(), [&](int r, unsigned) { find_run(tracer, r); });
}

int FirstHitBounds::tile_runs() const
{
    const size_t runs = (s_bounds_.size() + TILE_RUN - 1) / TILE_RUN;
    if (runs > size_t(INT32_MAX))
        fail("first pass: ", s_bounds_.size(), " tiles");
    return int(runs);
}

void FirstHitBounds::find_run(const Tracer &tracer, int run)
{
    const size_t end = std::min(s_bounds_.size(), (size_t(run) + 1) * TILE_RUN);
    for (size_t k = size_t(run) * TILE_RUN; k < end; ++k) {
        const int ty = int(k / size_t(tile_cols_)), tx = int(k % size_t(tile_cols_));
        s_bounds_[k] = tile_bound(tracer, ty * tile_, tx * tile_);
    }
}

bool FirstHitBounds::allocate(const Tracer &tracer)
{
    if (tracer.pyramid().levels() == 0)
        return false;
    tile_cols_ = (camera_.cols() + tile_ - 1) / tile_;
    const int tile_rows = (camera_.rows() + tile_ - 1) / tile_;
    s_bounds_.resize(size_t(tile_rows) * tile_cols_);
    for (int row = 0; row < camera_.rows(); ++row)
        row_offset_.push_back(uint32_t(row / tile_ * tile_cols_));
    for (int col = 0; col < camera_.cols(); ++col)
        col_tile_.push_back(uint32_t(col / tile_));
    return true;
}

double FirstHitBounds::tile_bound(const Tracer &tracer, int row0, int col0) const
{
    // the beam of the tile's corner pixels: every ray of the tile is an
    // affine mix of them in (x, y), so per axis within their extremes
    glm::dvec3 origin, forward, du, dv;
    camera_.linear_rays(origin, forward, du, dv);
    const int row1 = std::min(row0 + tile_, camera_.rows()) - 1;
    const int col1 = std::min(col0 + tile_, camera_.cols()) - 1;
    Beam beam;
    for (int k = 0; k < 4; ++k) {
        const int row = k & 1 ? row1 : row0, col = k & 2 ? col1 : col0;
        const glm::dvec2 p = camera_.pixel_ndc(row, col);
        if (camera_.parallel())
            beam.add(tracer.frame().local_from_exaggerated(origin + du * p.x + dv * p.y),
                     tracer.frame().local_direction_from_exaggerated(forward));
        else
            beam.add(
                tracer.frame().local_from_exaggerated(origin),
                tracer.frame().local_direction_from_exaggerated(forward + du * p.x + dv * p.y));
    }
    // best first: the frontier's nearest node bounds every cell below it
    const MinMaxPyramid &pyramid = tracer.pyramid();
    // room for what a small budget opens; a large one grows it (reserving
    // 4 * budget for every tile cost 9.6 MB a tile at a budget of 100,000)
    std::vector<Node> heap;
    heap.reserve(size_t(std::min(4 * budget_ + 4, 1024)));
    std::priority_queue<Node, std::vector<Node>, std::greater<Node>> frontier(
        std::greater<Node>(), std::move(heap));
    auto push = [&](int level, int x, int y) {
        const ZRange range = pyramid.node(level, x, y);
        if (range.empty())
            return;
        const glm::dvec3 low(double(x << level), double(y << level), range.low);
        const glm::dvec3 high(
            std::min(double((x + 1) << level), double(pyramid.cols(0))),
            std::min(double((y + 1) << level), double(pyramid.rows(0))), range.high);
        const double s = beam.enters(low, high);
        if (s < INF)
            frontier.push({s, level, x, y});
    };
    push(pyramid.levels() - 1, 0, 0);
    for (int opened = 0; !frontier.empty(); ++opened) {
        const Node node = frontier.top();
        if (node.level == 0 || opened == budget_)
            return node.s * (1 - MARGIN) - MARGIN;
        frontier.pop();
        const int level = node.level - 1;
        for (int k = 0; k < 4; ++k) {
            const int x = 2 * node.x + (k & 1), y = 2 * node.y + (k >> 1);
            if (x < pyramid.cols(level) && y < pyramid.rows(level))
                push(level, x, y);
        }
    }
    return INF;
}

double FirstHitBounds::t_start(int row, int col, const Ray &ray) const
{
    if (s_bounds_.empty())
        return 0;
    const double s = s_bound(row, col);
    if (s <= 0 || s == INF || camera_.parallel())
        return s; // a parallel ray's direction is unit: t = s
    // ray.direction = D / |D| with D . forward = 1 (du, dv are orthogonal
    // to the unit forward): |D| = 1 / (direction . forward)
    return s / glm::dot(ray.direction, camera_.forward());
}

size_t FirstHitBounds::empty_tiles() const
{
    return size_t(std::count(s_bounds_.begin(), s_bounds_.end(), INF));
}

} // namespace sbrt
