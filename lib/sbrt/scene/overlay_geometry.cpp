/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Ray geometry of boreholes and fence curtains
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/overlay_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace sbrt {

bool ray_cylinder(glm::dvec2 o, glm::dvec2 d, glm::dvec2 c, double r,
                  double &t0, double &t1)
{
    const glm::dvec2 q = o - c;
    const double a = glm::dot(d, d), c0 = glm::dot(q, q) - r * r;
    if (a == 0) {
        t0 = -std::numeric_limits<double>::infinity();
        t1 = std::numeric_limits<double>::infinity();
        return c0 < 0;
    }
    const double b = glm::dot(q, d); // half of the linear coefficient
    const double disc = b * b - a * c0;
    if (!(disc > 0))
        return false;
    // the numerically stable pair of roots
    const double s = std::sqrt(disc);
    const double k = b >= 0 ? -(b + s) : -(b - s);
    double r0 = k / a, r1 = k != 0 ? c0 / k : -r0;
    if (r0 > r1)
        std::swap(r0, r1);
    t0 = r0;
    t1 = r1;
    return true;
}

bool ray_panel(glm::dvec2 o, glm::dvec2 d, const FencePanel &panel, double &t,
               glm::dvec2 &normal)
{
    const glm::dvec2 e = panel.b - panel.a;
    const double denom = d.x * e.y - d.y * e.x; // cross(d, e)
    if (denom == 0)
        return false;
    const glm::dvec2 q = panel.a - o;
    t = (q.x * e.y - q.y * e.x) / denom;  // cross(q, e) / cross(d, e)
    const double u = (q.x * d.y - q.y * d.x) / denom; // cross(q, d) / ...
    if (!(u >= 0 && u <= 1))
        return false;
    normal = glm::normalize(glm::dvec2(-e.y, e.x));
    if (glm::dot(normal, d) > 0)
        normal = -normal;
    return true;
}

namespace {

/// Clips the segment a -> b to the box [low, high] (Liang-Barsky); false
/// where it misses the box.
bool clip_segment(glm::dvec2 &a, glm::dvec2 &b, glm::dvec2 low, glm::dvec2 high)
{
    double t0 = 0, t1 = 1;
    const glm::dvec2 d = b - a;
    for (int axis = 0; axis < 2; ++axis) {
        if (d[axis] == 0) {
            if (a[axis] < low[axis] || a[axis] > high[axis])
                return false;
            continue;
        }
        double ta = (low[axis] - a[axis]) / d[axis], tb = (high[axis] - a[axis]) / d[axis];
        if (ta > tb)
            std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1)
            return false;
    }
    const glm::dvec2 start = a;
    a = start + t0 * d;
    b = start + t1 * d;
    return true;
}

} // namespace

std::vector<uint64_t> cells_near_segment(const Frame &frame, glm::dvec2 a,
                                         glm::dvec2 b, double margin)
{
    const double ew = frame.ew_res(), ns = frame.ns_res();
    // only the part of the segment that can come near a cell: a segment
    // far outside the frame has no sample count or cell index in an int
    const glm::dvec2 pad(margin + 2 * ew, margin + 2 * ns);
    if (!(margin >= 0) ||
        !clip_segment(a, b, glm::dvec2(frame.west, frame.south) - pad,
                      glm::dvec2(frame.east, frame.north) + pad))
        return {};
    const double cells_long =
        std::max(std::fabs(b.x - a.x) / ew, std::fabs(b.y - a.y) / ns);
    const double reach_cols = std::ceil(margin / ew) + 1, reach_rows = std::ceil(margin / ns) + 1;
    if (cells_long > 4.0 * (frame.rows + frame.cols) || reach_cols > frame.cols ||
        reach_rows > frame.rows) {
        // a margin beyond the frame's size: every cell (a superset is safe)
        std::vector<uint64_t> all(frame.cells());
        for (uint64_t c = 0; c < all.size(); ++c)
            all[c] = c;
        return all;
    }
    // samples at most half a cell apart, each with the cells within the
    // margin (plus one cell, so rounding at a wall never loses a cell)
    const int samples = int(std::ceil(cells_long * 2)) + 1;
    const int reach_x = int(reach_cols), reach_y = int(reach_rows);
    std::vector<uint64_t> cells;
    for (int k = 0; k <= samples; ++k) {
        const glm::dvec2 p = a + (b - a) * (double(k) / samples);
        const int col = int(std::floor((p.x - frame.west) / ew));
        const int row = int(std::floor((frame.north - p.y) / ns));
        for (int r = std::max(0, row - reach_y);
             r <= std::min(frame.rows - 1, row + reach_y); ++r)
            for (int c = std::max(0, col - reach_x);
                 c <= std::min(frame.cols - 1, col + reach_x); ++c)
                cells.push_back(uint64_t(r) * uint64_t(frame.cols) + uint64_t(c));
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

} // namespace sbrt
