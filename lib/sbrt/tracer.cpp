/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Exact CPU ray caster
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "error.hpp"

namespace sbrt {

glm::dvec3 face_normal(Face face)
{
    switch (face) {
    case Face::west: return {-1, 0, 0};
    case Face::east: return {1, 0, 0};
    case Face::south: return {0, -1, 0};
    case Face::north: return {0, 1, 0};
    case Face::bottom: return {0, 0, -1};
    case Face::top: return {0, 0, 1};
    default: return {0, 0, 0};
    }
}

namespace {

constexpr double INF = std::numeric_limits<double>::infinity();

/// Face through which a ray moving along `axis` with sign of `d` enters.
Face entry_face(int axis, double d)
{
    if (axis == 0)
        return d > 0 ? Face::west : Face::east;
    if (axis == 1)
        return d > 0 ? Face::south : Face::north;
    return d > 0 ? Face::bottom : Face::top;
}

} // namespace

Tracer::Tracer(const Model &model, double zexag, std::vector<ClipPlane> planes)
    : model_(model), zexag_(zexag)
{
    if (!(zexag > 0) || !std::isfinite(zexag))
        fail("Tracer: vertical exaggeration ", zexag, " must be positive");
    const Frame &f = model.frame();
    for (uint64_t c = 0; c < f.cells(); ++c)
        if (model.stack_size(c))
            z_max_local_ = std::max(
                z_max_local_, double(model.intervals()[model.stack_end(c) - 1].top));
    scale_ = glm::dvec3(1.0 / f.ew_res(), 1.0 / f.ns_res(),
                        1.0 / (f.tb_res() * zexag));
    if (planes.size() > size_t(MAX_CLIP_PLANES))
        fail("Tracer: ", planes.size(), " clip planes, at most ", MAX_CLIP_PLANES);
    for (const ClipPlane &plane : planes) {
        // n . (x - p) = 0 in real space is n' . (x' - p') = 0 in exaggerated
        // space with n' = (nx, ny, nz / zexag)
        const glm::dvec3 n(plane.normal.x, plane.normal.y, plane.normal.z / zexag);
        const double length = glm::length(n);
        if (!(length > 0) || !std::isfinite(length) ||
            !std::isfinite(glm::length(plane.point)))
            fail("clip plane: the normal must not be zero and all values finite");
        const glm::dvec3 base(f.west, f.south, f.bottom);
        planes_.push_back({n / scale_ / length,
                           glm::dot(n, base - exaggerate(plane.point)) / length,
                           n / length});
    }
}

glm::dvec3 Tracer::exaggerate(glm::dvec3 p) const
{
    const double b = model_.frame().bottom;
    return {p.x, p.y, b + (p.z - b) * zexag_};
}

glm::dvec3 Tracer::unexaggerate(glm::dvec3 p) const
{
    const double b = model_.frame().bottom;
    return {p.x, p.y, b + (p.z - b) / zexag_};
}

glm::dvec3 Tracer::to_local(glm::dvec3 p) const
{
    const Frame &f = model_.frame();
    return (p - glm::dvec3(f.west, f.south, f.bottom)) * scale_;
}

glm::dvec3 Tracer::from_local(glm::dvec3 local) const
{
    const Frame &f = model_.frame();
    return {f.west + local.x * f.ew_res(), f.south + local.y * f.ns_res(),
            f.bottom + local.z * f.tb_res()};
}

double Tracer::top_elevation() const
{
    return model_.frame().bottom + z_max_local_ * model_.frame().tb_res();
}

glm::dvec3 Tracer::centre() const
{
    const Frame &f = model_.frame();
    return exaggerate({(f.east + f.west) / 2, (f.north + f.south) / 2,
                       (f.bottom + top_elevation()) / 2});
}

glm::dvec3 Tracer::corner(int k) const
{
    const Frame &f = model_.frame();
    return exaggerate({k & 1 ? f.east : f.west, k & 2 ? f.north : f.south,
                       k & 4 ? top_elevation() : f.bottom});
}

double Tracer::radius() const
{
    return glm::length(corner(7) - corner(0)) / 2;
}

bool Tracer::hit_in_cell(uint64_t cell, double z_in, double z_out, double oz,
                         double dz, double t_in, Face wall, Hit &hit) const
{
    const Interval *first = model_.intervals().data() + model_.stack_begin(cell);
    const Interval *last = model_.intervals().data() + model_.stack_end(cell);
    // nothing to find where the ray stays at or above the stack's top
    if (first == last || std::min(z_in, z_out) >= double((last - 1)->top))
        return false;
    auto below_of = [&](const Interval *k) {
        return k == first ? 0.0 : double((k - 1)->top);
    };
    if (dz < 0) {
        // descending: intervals (bottom, top]; the one holding z_in, then
        // down while their tops stay above z_out
        const Interval *k = std::lower_bound(
            first, last, z_in,
            [](const Interval &iv, double z) { return double(iv.top) < z; });
        if (k != last && k->material != EMPTY) {
            hit = {t_in, k->material, wall};
            return true;
        }
        for (const Interval *j = k; j-- > first;) {
            if (!(double(j->top) > z_out))
                return false;
            if (j->material != EMPTY) {
                hit = {(double(j->top) - oz) / dz, j->material, Face::top};
                return true;
            }
        }
        return false;
    }
    // ascending or level: intervals [bottom, top)
    const Interval *k = std::upper_bound(
        first, last, z_in,
        [](double z, const Interval &iv) { return z < double(iv.top); });
    if (k == last)
        return false;
    if (k->material != EMPTY) {
        hit = {t_in, k->material, wall};
        return true;
    }
    if (dz == 0)
        return false;
    for (const Interval *j = k + 1; j < last; ++j) {
        const double bottom = below_of(j);
        if (!(bottom < z_out))
            return false;
        if (j->material != EMPTY) {
            hit = {(bottom - oz) / dz, j->material, Face::bottom};
            return true;
        }
    }
    return false;
}

Hit Tracer::trace(const Ray &ray) const
{
    const Frame &f = model_.frame();
    const glm::dvec3 o = to_local(ray.origin);
    glm::dvec3 d = local_direction(ray.direction);
    for (int a = 0; a < 3; ++a)
        if (d[a] == 0)
            d[a] = 0; // normalise -0

    // 1. slab clip to the box [0, cols] x [0, rows] x [0, z_max]
    const glm::dvec3 high(f.cols, f.rows, z_max_local_);
    double t_near = -INF, t_far = INF;
    int near_axis = -1;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0) {
            if (o[a] < 0 || o[a] > high[a])
                return {};
            continue;
        }
        double t0 = (0 - o[a]) / d[a], t1 = (high[a] - o[a]) / d[a];
        if (t0 > t1)
            std::swap(t0, t1);
        if (t0 > t_near) {
            t_near = t0;
            near_axis = a;
        }
        t_far = std::min(t_far, t1);
    }
    Face wall = near_axis >= 0 ? entry_face(near_axis, d[near_axis]) : Face::none;
    // clip planes: the kept side f(t) = a + b t <= 0 narrows [t_near, t_far]
    int entry_plane = -1;
    for (size_t k = 0; k < planes_.size(); ++k) {
        const double a = glm::dot(planes_[k].n, o) + planes_[k].c;
        const double b = glm::dot(planes_[k].n, d);
        if (b == 0) {
            if (a > 0)
                return {}; // the ray runs in the removed half-space
            continue;
        }
        const double t = -a / b;
        if (b > 0)
            t_far = std::min(t_far, t);
        else if (t > t_near) {
            t_near = t;
            wall = Face::plane;
            entry_plane = int(k);
        }
    }
    if (t_near < 0) {
        t_near = 0; // the camera is inside the box
        wall = Face::none;
        entry_plane = -1;
    }
    if (!(t_near <= t_far) || z_max_local_ <= 0)
        return {};

    // 2. 2D DDA (Amanatides-Woo) over the cells from the entry point
    const glm::dvec3 p = o + t_near * d;
    int ix = std::clamp(int(std::floor(p.x)), 0, f.cols - 1);
    int iy = std::clamp(int(std::floor(p.y)), 0, f.rows - 1);
    const int step_x = d.x > 0 ? 1 : -1, step_y = d.y > 0 ? 1 : -1;
    double t_max_x = d.x != 0 ? ((ix + (d.x > 0)) - o.x) / d.x : INF;
    double t_max_y = d.y != 0 ? ((iy + (d.y > 0)) - o.y) / d.y : INF;
    const double t_delta_x = d.x != 0 ? std::fabs(1 / d.x) : INF;
    const double t_delta_y = d.y != 0 ? std::fabs(1 / d.y) : INF;
    double t_in = t_near;
    // bounded: a ray crosses at most cols + rows cells
    for (int steps = 0; steps <= f.cols + f.rows + 1; ++steps) {
        const double t_out = std::min({t_max_x, t_max_y, t_far});
        const uint64_t cell = model_.cell_index(f.rows - 1 - iy, ix);
        Hit hit;
        if (hit_in_cell(cell, o.z + t_in * d.z, o.z + t_out * d.z, o.z, d.z,
                        t_in, wall, hit)) {
            if (hit.face == Face::plane) {
                hit.plane = entry_plane;
                hit.normal = planes_[size_t(entry_plane)].shading_normal;
            }
            else
                hit.normal = hit.face == Face::none ? -ray.direction
                                                    : face_normal(hit.face);
            hit.point = from_local(o + hit.t * d);
            return hit;
        }
        if (t_out >= t_far)
            break;
        if (t_max_x < t_max_y) {
            ix += step_x;
            t_in = t_max_x;
            t_max_x += t_delta_x;
            wall = entry_face(0, d.x);
        }
        else {
            iy += step_y;
            t_in = t_max_y;
            t_max_y += t_delta_y;
            wall = entry_face(1, d.y);
        }
        if (ix < 0 || ix >= f.cols || iy < 0 || iy >= f.rows)
            break;
    }
    return {};
}

} // namespace sbrt
