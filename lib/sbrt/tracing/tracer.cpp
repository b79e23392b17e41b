/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Exact CPU ray caster
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "tracing/tracer.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "tracing/cell_stepper.hpp"
#include "util/error.hpp"
#include "tracing/tracer_walk.hpp"

namespace sbrt {

using namespace tracer_detail;

namespace {

/// clip_to_box along one axis (glm's operator[] switches on its index:
/// the axes are passed as scalars).
inline bool clip_axis(double o, double d, double inv_d, double low, double high, int axis,
                      double &t_near, double &t_far, int &near_axis)
{
    if (d == 0)
        return !(o < low || o > high);
    double t0 = (low - o) * inv_d, t1 = (high - o) * inv_d;
    if (t0 > t1)
        std::swap(t0, t1);
    if (t0 > t_near) {
        t_near = t0;
        near_axis = axis;
    }
    t_far = std::min(t_far, t1);
    return true;
}

} // namespace

bool clip_to_box(glm::dvec3 o, glm::dvec3 d, glm::dvec3 inv_d, glm::dvec3 low,
                 glm::dvec3 high, double &t_near, double &t_far, int &near_axis)
{
    return clip_axis(o.x, d.x, inv_d.x, low.x, high.x, 0, t_near, t_far, near_axis) &&
           clip_axis(o.y, d.y, inv_d.y, low.y, high.y, 1, t_near, t_far, near_axis) &&
           clip_axis(o.z, d.z, inv_d.z, low.z, high.z, 2, t_near, t_far, near_axis);
}

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

Tracer::Tracer(const Model &model, double zexag, std::vector<ClipPlane> planes)
    : Tracer(model, zexag, Scene{std::move(planes), {}, {}, 0, {}, {}, true})
{
}

namespace {

/// The highest top a ray can meet: the model's, or a borehole's log's.
double highest_top_drawn(const Model &model, const Scene &scene)
{
    double top = highest_top_local(model);
    for (const Borehole &b : scene.boreholes)
        for (const std::vector<Interval> *stack : {&b.stack, &b.model_stack})
            if (!stack->empty())
                top = std::max(top, double(stack->back().top));
    return top;
}

} // namespace

Tracer::Tracer(const Model &model, double zexag, Scene scene)
    : model_(model), scene_(std::move(scene)),
      frame_(model.frame(), zexag, highest_top_drawn(model, scene_))
{
    const Frame &f = model.frame();
    const glm::dvec3 scale_ = frame_.scale();
    const std::vector<ClipPlane> &planes = scene_.planes;
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
                           glm::dot(n, base - frame_.exaggerated_from_map(plane.point)) / length,
                           n / length});
    }
    const Translucency &tr = scene_.translucency;
    if (!tr.empty() && (tr.extinction.size() != model.materials().size() ||
                        tr.color.size() != model.materials().size()))
        fail("Tracer: translucency given for ", tr.extinction.size(),
             " materials, the model has ", model.materials().size());
    if (!scene_.boreholes.empty() && !(scene_.borehole_radius > 0))
        fail("Tracer: the borehole radius must be positive");
    if (!scene_.hidden.empty() && scene_.hidden.size() != model.materials().size())
        fail("Tracer: hidden materials given for ", scene_.hidden.size(),
             " materials, the model has ", model.materials().size());
    if (model.is_paged() && (!scene_.boreholes.empty() || !scene_.fence.empty()))
        fail("Tracer: boreholes and a fence read the stacks of a decoded model, not a "
             "paged one");
    if (!scene_.hidden.empty() && (!scene_.boreholes.empty() || !scene_.fence.empty()))
        fail("Tracer: materials hidden while tracing with boreholes or a fence (remove "
             "them from the model: hide_materials)");
    index_overlays();
    build_pyramid();
    overlay_boxes_ = find_overlay_boxes(); // with the pyramid: borehole_top reads it
}

void Tracer::build_pyramid()
{
    if (!scene_.skip_empty_space || !scene_.draw_model)
        return;
    const Frame &f = model_.frame();
    // a column that lies wholly on the removed side of a clip plane holds
    // nothing
    const auto clip = [&](int x, int y, ZRange &range) {
        for (const LocalPlane &plane : planes_) {
            bool removed = true;
            for (int k = 0; k < 8 && removed; ++k) {
                const glm::dvec3 l(x + (k & 1), y + ((k >> 1) & 1),
                                   k & 4 ? range.high : range.low);
                removed = glm::dot(plane.n, l) + plane.c > 0;
            }
            if (removed) {
                range = ZRange();
                return;
            }
        }
    };
    if (overlay_items_.empty() && planes_.empty()) {
        pyramid_ = MinMaxPyramid(model_, KeepEveryCell(), scene_.hidden);
        return;
    }
    pyramid_ = MinMaxPyramid(model_, [&](int x, int y, ZRange &range) {
        const uint64_t cell = model_.cell_index(f.rows - 1 - y, x);
        if (!overlay_items_.empty() &&
            overlay_offsets_[cell] != overlay_offsets_[cell + 1]) {
            // overlays: walked up to the highest a ray can meet there (a
            // curtain shows the model's class: its top; a cylinder its
            // log, or the model's stack at its axis), also where the
            // model holds nothing
            float top = range.empty() ? 0.0f : range.high;
            for (uint32_t k = overlay_offsets_[cell]; k < overlay_offsets_[cell + 1]; ++k) {
                if (overlay_items_[k] & OVERLAY_PANEL)
                    continue;
                const Borehole &b = scene_.boreholes[overlay_items_[k]];
                for (const std::vector<Interval> *stack : {&b.stack, &b.model_stack})
                    if (!stack->empty())
                        top = std::max(top, stack->back().top);
            }
            range = {0, top};
            return;
        }
        if (!range.empty())
            clip(x, y, range);
    }, scene_.hidden);
    if (!overlay_items_.empty())
        model_pyramid_ = MinMaxPyramid(model_, [&](int x, int y, ZRange &range) {
            if (!range.empty())
                clip(x, y, range);
        });
}

bool Tracer::meet(uint32_t material, double t_enter, double t_exit, const Entry &entry,
                  Walk &walk) const
{
    // a hidden material is crossed as air
    if (material == EMPTY || (!scene_.hidden.empty() && scene_.hidden[material]))
        return false;
    const Translucency &tr = scene_.translucency;
    if (tr.opaque(material)) {
        walk.hit.t = t_enter;
        walk.hit.material = material;
        walk.hit.face = entry.face;
        walk.hit.plane = int8_t(entry.plane);
        walk.hit.normal = entry.face >= Face::west && entry.face <= Face::top
                              ? face_normal(entry.face)
                              : entry.normal;
        return true;
    }
    // Beer-Lambert over the exact length the ray travels in the interval;
    // a zero-length crossing (a fence curtain, a surface) absorbs alpha
    const double length = t_exit > t_enter
                              ? (t_exit - t_enter) * glm::length(walk.ray.direction)
                              : tr.length;
    const double keep = std::exp(-tr.extinction[material] * length);
    walk.hit.veil += glm::vec3(walk.hit.transmittance * (1 - keep) * tr.color[material]);
    walk.hit.transmittance = float(walk.hit.transmittance * keep);
    return walk.hit.transmittance < MIN_TRANSMITTANCE;
}

template <typename Record>
bool Tracer::walk_stack(const Record *first, const Record *last, double t_a,
                        double t_b, const Entry &entry, Walk &walk) const
{
    const double oz = walk.o.z, dz = walk.d.z;
    const double z_a = oz + t_a * dz, z_b = oz + t_b * dz;
    // nothing to find where the ray stays at or above the stack's top
    if (first == last || std::min(z_a, z_b) >= double((last - 1)->top))
        return false;
    const double inv_dz = walk.inv_d.z;
    auto t_at = [&](auto z) { return (double(z) - oz) * inv_dz; };
    const Entry top{Face::top}, bottom{Face::bottom};
    if (dz < 0) {
        // descending: intervals (bottom, top]; the one holding z_a, then
        // down while their tops stay above z_b
        const Record *k = std::lower_bound(
            first, last, z_a,
            [](const Record &iv, double z) { return double(iv.top) < z; });
        for (const Record *j = k;; --j) {
            if (j != last) {
                const double exit = j > first ? std::min(t_b, t_at((j - 1)->top)) : t_b;
                if (meet(j->material, j == k ? t_a : t_at(j->top), exit,
                         j == k ? entry : top, walk))
                    return true;
            }
            if (j == first || !(double((j - 1)->top) > z_b))
                return false;
        }
    }
    // ascending or level: intervals [bottom, top)
    const Record *k = std::upper_bound(
        first, last, z_a,
        [](double z, const Record &iv) { return z < double(iv.top); });
    for (const Record *j = k; j != last; ++j) {
        if (j != k && !(double((j - 1)->top) < z_b))
            return false;
        const double exit = dz == 0 ? t_b : std::min(t_b, t_at(j->top));
        if (meet(j->material, j == k ? t_a : t_at((j - 1)->top), exit,
                 j == k ? entry : bottom, walk))
            return true;
        if (dz == 0)
            return false;
    }
    return false;
}
template bool Tracer::walk_stack(const Interval *, const Interval *, double, double,
                                 const Entry &, Walk &) const;
template bool Tracer::walk_stack(const CompactInterval *, const CompactInterval *, double,
                                 double, const Entry &, Walk &) const;

bool Tracer::cross_cell(uint64_t cell, double t_in, double t_out, const Entry &entry,
                        Walk &walk) const
{
    if (!overlay_items_.empty() &&
        overlay_offsets_[cell] != overlay_offsets_[cell + 1])
        return cross_overlays(cell, t_in, t_out, entry, walk);
    if (!scene_.draw_model)
        return false;
    if (const StackPages *pages = model_.pages()) {
        if (pages->has_column_tops())
            if (const std::optional<bool> met =
                    cross_top_interval(*pages, cell, t_in, t_out, entry, walk))
                return *met;
        const int cols = model_.frame().cols;
        const int row = int(cell / uint64_t(cols)), col = int(cell % uint64_t(cols));
        const StackBlock &block = walk.pin.at(*pages, row, col);
        const StackRange stack = block.range(row, col);
        return block.intervals.visit([&](const auto *records) {
            return walk_stack(records + stack.begin, records + stack.end, t_in, t_out, entry,
                              walk);
        });
    }
    const StackRange stack = model_.stack(cell);
    return model_.intervals().visit([&](const auto *records) {
        return walk_stack(records + stack.begin, records + stack.end, t_in, t_out, entry, walk);
    });
}

std::optional<bool> Tracer::cross_top_interval(const StackPages &pages, uint64_t cell,
                                               double t_in, double t_out, const Entry &entry,
                                               Walk &walk) const
{
    return pages.column_tops().visit([&](const auto *tops) -> std::optional<bool> {
        using Record = RecordOf<decltype(tops)>;
        const Record top = tops[cell]; // its material, and its bottom in `top`
        if (top.material == EMPTY)
            return false; // an empty column
        // as walk_stack reckons the ray's heights in the cell
        const double z_a = walk.o.z + t_in * walk.d.z, z_b = walk.o.z + t_out * walk.d.z;
        const double bottom = double(top.top);
        if (!(z_a > bottom))
            return std::nullopt; // it enters below: the block's stack
        // the stack as walk_stack reads it down to that bottom: the
        // interval below ends there (only its top is read), then the top
        // one, up to the column's range; a column of one interval is that
        // alone
        const auto high = decltype(top.top)(pages.column_ranges()[cell].high);
        const Record stack[2] = {{EMPTY, top.top}, {top.material, high}};
        // a ray that goes on below the bottom (descending, through a top
        // interval hidden or translucent) is walked again in the block's
        // stack, from what it had met before
        const bool goes_below = !(std::min(z_a, z_b) > bottom);
        const Hit before = goes_below ? walk.hit : Hit();
        if (walk_stack(top.top == 0 ? stack + 1 : stack, stack + 2, t_in, t_out, entry, walk))
            return true;
        if (!goes_below)
            return false;
        walk.hit = before;
        return std::nullopt;
    });
}

bool Tracer::leave_block(const Walk &walk, double z_in, double t_far, int ix, int iy,
                         Jump &jump) const
{
    const Frame &f = model_.frame();
    const glm::dvec3 &o = walk.o, &d = walk.d;
    // the largest block so far: its exit and the axis the ray leaves along
    // (-1: none); kept in plain locals, the Jump is made once at the end
    double t_exit = 0;
    int exit_axis = -1, x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    for (int level = 1; level < pyramid_.levels(); ++level) {
        const ZRange node = pyramid_.node(level, ix >> level, iy >> level);
        if (!passes(node, z_in, z_in))
            break; // the ray starts among the node's material
        // the node's cells [nx0, nx1) x [ny0, ny1) and where the ray leaves them
        const int nx0 = (ix >> level) << level, ny0 = (iy >> level) << level;
        const int nx1 = std::min(nx0 + (1 << level), f.cols);
        const int ny1 = std::min(ny0 + (1 << level), f.rows);
        const double tx = d.x > 0   ? (nx1 - o.x) * walk.inv_d.x
                          : d.x < 0 ? (nx0 - o.x) * walk.inv_d.x
                                    : INF;
        const double ty = d.y > 0   ? (ny1 - o.y) * walk.inv_d.y
                          : d.y < 0 ? (ny0 - o.y) * walk.inv_d.y
                                    : INF;
        const double t = std::min(std::min(tx, ty), t_far);
        if (!passes(node, z_in, o.z + t * d.z))
            break;
        t_exit = t;
        exit_axis = tx < ty ? 0 : 1; // a tie goes the way the cell walk goes
        x0 = nx0, x1 = nx1, y0 = ny0, y1 = ny1;
    }
    if (exit_axis < 0)
        return false;
    // the cell beyond
    if (exit_axis == 0)
        jump = {t_exit, d.x > 0 ? x1 : x0 - 1,
                std::clamp(int(std::floor(o.y + t_exit * d.y)), y0, y1 - 1),
                d.x > 0 ? Face::west : Face::east};
    else
        jump = {t_exit, std::clamp(int(std::floor(o.x + t_exit * d.x)), x0, x1 - 1),
                d.y > 0 ? y1 : y0 - 1, d.y > 0 ? Face::south : Face::north};
    return true;
}

Hit Tracer::trace(const Ray &ray, double t_start) const
{
    Hit hit;
    trace_into(ray, t_start, hit);
    return hit;
}

bool Tracer::clip_walk(const Walk &walk, double t_start, double &t_near, double &t_far,
                       Entry &wall) const
{
    const glm::dvec3 o = walk.o, d = walk.d;
    // the slab clip to the box [0, cols] x [0, rows] x [0, z_max] (the
    // overlays' cells only, where the model is not drawn)
    t_near = -INF;
    t_far = INF;
    int near_axis = -1;
    if (!clip_to_box(o, d, walk.inv_d, glm::dvec3(box_low_, 0),
                     glm::dvec3(box_high_, frame_.top_local()), t_near, t_far, near_axis))
        return false;
    wall = Entry{};
    if (near_axis >= 0)
        wall.face = entry_face(near_axis, d[near_axis]);
    // clip planes: the kept side f(t) = a + b t <= 0 narrows [t_near, t_far]
    for (size_t k = 0; k < planes_.size(); ++k) {
        const double a = glm::dot(planes_[k].n, o) + planes_[k].c;
        const double b = glm::dot(planes_[k].n, d);
        if (b == 0) {
            if (a > 0)
                return false; // the ray runs in the removed half-space
            continue;
        }
        const double t = -a / b;
        if (b > 0)
            t_far = std::min(t_far, t);
        else if (t > t_near) {
            t_near = t;
            wall = {Face::plane, planes_[k].shading_normal, int(k)};
        }
    }
    // the walk starts no earlier than the camera (t = 0: the camera is in
    // the box) nor than t_start (nothing to meet before: in the air)
    const double start = std::max(t_start, 0.0);
    if (t_near < start) {
        t_near = start;
        wall = {Face::none, -walk.ray.direction};
    }
    return t_near <= t_far && frame_.top_local() > 0;
}

void Tracer::trace_into(const Ray &ray, double t_start, Hit &hit) const
{
    StackPin pin;
    trace_into(ray, t_start, hit, pin);
}

void Tracer::trace_into(const Ray &ray, double t_start, Hit &hit, StackPin &pin) const
{
    const Frame &f = model_.frame();
    hit = Hit();
    Walk walk{ray, frame_.local_from_exaggerated(ray.origin),
              frame_.local_direction_from_exaggerated(ray.direction), hit, pin};
    const glm::dvec3 o = walk.o;
    glm::dvec3 &d = walk.d;
    for (int a = 0; a < 3; ++a)
        if (d[a] == 0)
            d[a] = 0; // normalise -0
    walk.inv_d = 1.0 / d;

    // 1. the stretch of the ray in the box and on the kept side of the
    // clip planes, and the surface it enters through
    double t_near = -INF, t_far = INF;
    Entry wall;
    if (!clip_walk(walk, t_start, t_near, t_far, wall))
        return;

    // only a few overlays and no model: meet each overlay directly, no
    // walk over the cells between them
    if (!scene_.draw_model && all_overlays_.size() <= DIRECT_OVERLAYS) {
        std::vector<Event> events;
        overlay_events(all_overlays_.data(), all_overlays_.data() + all_overlays_.size(),
                       t_near, t_far, walk, events);
        if (cross_events(events, t_near, t_far, wall, nullptr, walk) &&
            walk.hit.is_hit())
            walk.hit.point = frame_.map_from_local(o + walk.hit.t * d);
        return;
    }

    // 2. the cells from the entry point (a 2D DDA), skipping the blocks
    // of cells the pyramid says hold nothing at the ray's height
    CellStepper cells(o.x, o.y, d.x, d.y, walk.inv_d.x, walk.inv_d.y, t_near, t_far,
                      wall.face, f.cols, f.rows);
    // the block of 2 x 2 cells the ray last failed to skip: while it is in
    // there, the cell walk goes on without trying (close above material, a
    // try costs more than it saves)
    int stuck_x = -1, stuck_y = -1;
    const bool skipping = pyramid_.levels() > 0;
    // where level 0 holds hidden or cut material the levels above leave
    // out, a cell with material may still lie in a block with nothing drawn
    const bool try_every_cell = pyramid_.level_0_wider();
    // bounded: a ray crosses at most cols + rows cells (a jump counts as one)
    for (int steps = 0; !cells.done() && steps <= f.cols + f.rows + 1;
         ++steps, wall.face = cells.face(), wall.plane = -1) {
        // (past the first cell, the entry is a cell's face: its normal is
        // face_normal's, the Entry's is not read)
        const int ix = cells.x(), iy = cells.y();
        const double t_in = cells.t_in(), t_out = cells.t_out();
        const double z_in = o.z + t_in * d.z;
        const bool nothing_here =
            skipping && passes(pyramid_.node(0, ix, iy), z_in, o.z + t_out * d.z);
        if ((nothing_here || try_every_cell) && ((ix >> 1) != stuck_x || (iy >> 1) != stuck_y)) {
            // leave the largest block of cells around that holds nothing
            // at the ray's height
            Jump jump;
            if (leave_block(walk, z_in, t_far, ix, iy, jump)) {
                cells.jump_to(jump.ix, jump.iy, jump.t, jump.face);
                continue;
            }
            stuck_x = ix >> 1;
            stuck_y = iy >> 1;
        }
        if (!nothing_here && cross_cell(model_.cell_index(f.rows - 1 - iy, ix), t_in, t_out,
                                        wall, walk)) {
            if (walk.hit.is_hit())
                walk.hit.point = frame_.map_from_local(o + walk.hit.t * d);
            return;
        }
        cells.next();
    }
    return;
}

} // namespace sbrt
