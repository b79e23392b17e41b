/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Views turned into cameras
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/view.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

#include <glm/geometric.hpp>

#include "model/stack_pages.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

/// Right and up of a view along `forward`, with the tangents of its half
/// angles.
struct ViewPlane {
    ViewPlane(glm::dvec3 forward_, double fov, double aspect) : forward(forward_)
    {
        view_basis(forward, right, up);
        right = glm::normalize(right);
        up = glm::normalize(up);
        tan_y = std::tan(fov * M_PI / 360);
        tan_x = tan_y * aspect;
    }
    glm::dvec3 forward, right, up;
    double tan_x = 1, tan_y = 1;
};

/// Extent of `points` seen from `eye` along the plane's forward, in
/// normalised device coordinates (perspective) or map units (parallel,
/// eye unused): x_low, x_high, y_low, y_high; false where a point is not
/// in front of a perspective eye.
bool extent(const std::vector<glm::dvec3> &points, const ViewPlane &plane,
            const glm::dvec3 *eye, double e[4])
{
    e[0] = e[2] = HUGE_VAL;
    e[1] = e[3] = -HUGE_VAL;
    for (const glm::dvec3 &p : points) {
        const glm::dvec3 v = eye ? p - *eye : p;
        double x = glm::dot(v, plane.right), y = glm::dot(v, plane.up);
        if (eye) {
            const double z = glm::dot(v, plane.forward);
            if (!(z > 0))
                return false;
            x /= plane.tan_x * z;
            y /= plane.tan_y * z;
        }
        e[0] = std::min(e[0], x);
        e[1] = std::max(e[1], x);
        e[2] = std::min(e[2], y);
        e[3] = std::max(e[3], y);
    }
    return true;
}

glm::dvec3 points_centre(const std::vector<glm::dvec3> &points)
{
    glm::dvec3 low(HUGE_VAL), high(-HUGE_VAL);
    for (const glm::dvec3 &p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    return (low + high) / 2.0;
}

/// max over the points of side * (p . axis) - t * (p . forward): where a
/// side plane of half-angle tangent t must pass to hold them all.
double support(const std::vector<glm::dvec3> &points, const ViewPlane &plane,
               const glm::dvec3 &axis, double side, double t)
{
    double h = -HUGE_VAL;
    for (const glm::dvec3 &p : points)
        h = std::max(h, side * glm::dot(p, axis) - t * glm::dot(p, plane.forward));
    return h;
}

/// The eye of a perspective view along plane.forward whose frustum,
/// narrowed to 95 %, touches the points on both sides of its tighter axis
/// and holds them centred on the other (exact: each side plane passes
/// through its extreme point). In the basis right, up, forward the eye is
/// (x, y, z): x - t z = h_right and -x - t z = h_left give x and z.
glm::dvec3 framing_eye(const std::vector<glm::dvec3> &points, const ViewPlane &plane)
{
    const double tx = 0.95 * plane.tan_x, ty = 0.95 * plane.tan_y;
    auto depth = [&](const glm::dvec3 &axis, double t) {
        return -(support(points, plane, axis, 1, t) + support(points, plane, axis, -1, t)) /
               (2 * t);
    };
    const double z = std::min(depth(plane.right, tx), depth(plane.up, ty));
    // on each axis the half angle whose planes meet at depth z (the depth
    // grows with the angle), then the centre between them
    auto across = [&](const glm::dvec3 &axis, double t_max) {
        double low = 0, high = t_max;
        for (int i = 0; i < 60; ++i) {
            const double mid = (low + high) / 2;
            (depth(axis, mid) >= z ? high : low) = mid;
        }
        return (support(points, plane, axis, 1, high) -
                support(points, plane, axis, -1, high)) /
               2;
    };
    return across(plane.right, tx) * plane.right + across(plane.up, ty) * plane.up +
           z * plane.forward;
}

} // namespace

std::vector<glm::dvec3> framing_hull(const Model &model, const CoordinateFrame &frame)
{
    const Frame &f = model.frame();
    const int blocks_x = std::min(8, f.cols), blocks_y = std::min(8, f.rows);
    std::vector<double> top(size_t(blocks_x * blocks_y), -HUGE_VAL);
    // each block's columns are a run of the row: the highest of each run
    std::vector<int> run_end(static_cast<size_t>(blocks_x));
    for (int bx = 0; bx < blocks_x; ++bx) // the first col with col * blocks_x / cols > bx
        run_end[size_t(bx)] = int(((int64_t(bx) + 1) * f.cols + blocks_x - 1) / blocks_x);
    // a paged model's column ranges read directly: the loop over 7.4
    // million columns (national) with nothing else in it
    const ColumnRangeArray *ranges = model.pages() && model.pages()->has_column_ranges()
                                         ? &model.pages()->column_ranges()
                                         : nullptr;
    // rows in takes on all cores, each take's highest merged
    std::mutex merge;
    for_each_take(0, f.rows, 0, 256, [&](int first_row, int end_row) {
        std::vector<double> take_top(top.size(), -HUGE_VAL);
        auto scan_rows = [&](const auto &stack_top) {
            for (int row = first_row; row < end_row; ++row) {
                // row 0 is the north edge
                const int by = (f.rows - 1 - row) * blocks_y / f.rows;
                const uint64_t first = model.cell_index(row, 0);
                for (int bx = 0, col = 0; bx < blocks_x; ++bx) {
                    double highest = -HUGE_VAL;
                    for (; col < run_end[size_t(bx)]; ++col)
                        highest = std::max(highest, stack_top(first + uint64_t(col)));
                    double &t = take_top[size_t(by * blocks_x + bx)];
                    t = std::max(t, highest);
                }
            }
        };
        if (ranges) // Model::stack_top's answer for these
            ranges->visit([&](const auto *range) {
                scan_rows([range](uint64_t cell) {
                    const ZRange r = widened(range[cell]);
                    return r.empty() ? -1.0 : double(r.high);
                });
            });
        else
            scan_rows([&model](uint64_t cell) { return model.stack_top(cell); });
        const std::lock_guard<std::mutex> lock(merge);
        for (size_t i = 0; i < top.size(); ++i)
            top[i] = std::max(top[i], take_top[i]);
    });
    std::vector<glm::dvec3> points;
    for (int by = 0; by < blocks_y; ++by)
        for (int bx = 0; bx < blocks_x; ++bx) {
            const double t = top[size_t(by * blocks_x + bx)];
            if (t < 0) // no stack in the block
                continue;
            for (int k = 0; k < 8; ++k) {
                // block edges in cells from the west and south edges
                const double x = double((bx + (k & 1)) * f.cols) / blocks_x;
                const double y = double((by + (k >> 1 & 1)) * f.rows) / blocks_y;
                points.push_back(
                    frame.exaggerated_from_map(frame.map_from_local({x, y, k & 4 ? t : 0.0})));
            }
        }
    if (points.empty()) // an empty model: its box
        for (int k = 0; k < 8; ++k)
            points.push_back(frame.corner(k));
    return points;
}

double framing_distance(const std::vector<glm::dvec3> &points, glm::dvec3 target,
                        glm::dvec3 offset, double fov, double aspect)
{
    const ViewPlane plane(-offset, fov, aspect);
    auto fits = [&](double d) {
        const glm::dvec3 eye = target + offset * d;
        double e[4];
        return extent(points, plane, &eye, e) && -e[0] <= 0.95 && e[1] <= 0.95 &&
               -e[2] <= 0.95 && e[3] <= 0.95;
    };
    // bisection between the target and a distance that fits: the sphere
    // around the points within the narrower of the two half angles (a
    // portrait image's is the horizontal one), doubled until it fits
    double reach = 0;
    for (const glm::dvec3 &p : points)
        reach = std::max(reach, glm::length(p - target));
    const double half_angle = std::atan(std::min(plane.tan_x, plane.tan_y));
    double low = 0, high = reach / std::sin(half_angle) * 1.1 + 1e-9;
    for (int i = 0; i < 60 && !fits(high); ++i)
        high *= 2;
    for (int i = 0; i < 60; ++i) {
        const double mid = (low + high) / 2;
        (fits(mid) ? high : low) = mid;
    }
    return high;
}

glm::dvec3 orthographic_start(const CoordinateFrame &frame, glm::dvec3 target,
                              glm::dvec3 offset)
{
    const double reach = frame.radius() + glm::length(frame.centre() - target);
    return target + offset * (reach + frame.radius());
}

Camera view_camera(const View &view, const Model &model, const CoordinateFrame &frame,
                   int rows, int cols)
{
    if (view.kind == ViewKind::top)
        fail("view_camera: a top view is the 2D region's (Camera::top)");
    const double aspect = double(cols) / rows;
    const bool framed = !view.position;
    const std::vector<glm::dvec3> hull =
        framed || !view.ortho_height ? framing_hull(model, frame) : std::vector<glm::dvec3>();
    glm::dvec3 target =
        view.target ? frame.exaggerated_from_map(*view.target) : points_centre(hull);
    glm::dvec3 offset; // unit, from the target to the camera
    if (view.position) {
        offset = glm::normalize(frame.exaggerated_from_map(*view.position) - target);
    }
    else {
        // around the target: azimuth is where the camera looks from
        const double az = view.azimuth * M_PI / 180, el = view.elevation * M_PI / 180;
        offset = {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
    }
    const ViewPlane plane(-offset, view.fov, aspect);

    if (view.kind == ViewKind::orthographic) {
        double e[4] = {-1, 1, -1, 1};
        if (!hull.empty())
            extent(hull, plane, nullptr, e);
        if (framed && !view.target) {
            // the hull's extent centred (parallel rays: in one step)
            const double x = (e[0] + e[1]) / 2, y = (e[2] + e[3]) / 2;
            target += x * plane.right + y * plane.up -
                      glm::dot(target, plane.right) * plane.right -
                      glm::dot(target, plane.up) * plane.up;
            for (double *v : {&e[0], &e[1]})
                *v -= x;
            for (double *v : {&e[2], &e[3]})
                *v -= y;
        }
        const double height =
            view.ortho_height
                ? *view.ortho_height
                : std::max({-e[2], e[3], -e[0] / aspect, e[1] / aspect}) * 2 / 0.95;
        // rays start outside the model whatever position= says
        return Camera::orthographic(orthographic_start(frame, target, offset), target,
                                    height, rows, cols);
    }
    if (!framed)
        return Camera::perspective(frame.exaggerated_from_map(*view.position), target, view.fov,
                                   rows, cols);
    if (view.target || view.distance)
        return Camera::perspective(
            target + offset * (view.distance ? *view.distance
                                             : framing_distance(hull, target, offset,
                                                                view.fov, aspect)),
            target, view.fov, rows, cols);
    // (target: the hull's centre) looked at from the eye, on its axis
    const glm::dvec3 eye = framing_eye(hull, plane);
    return Camera::perspective(eye, eye + plane.forward * glm::dot(target - eye, plane.forward),
                               view.fov, rows, cols);
}

} // namespace sbrt
