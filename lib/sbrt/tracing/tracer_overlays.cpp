/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The tracer's overlays: boreholes (cylinders, split logs) and
 *            fence curtains, indexed per cell and met along a ray
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/overlay_geometry.hpp"
#include "tracing/tracer_walk.hpp"

namespace sbrt {

using namespace tracer_detail;

void Tracer::index_overlays()
{
    const Frame &f = model_.frame();
    box_low_ = glm::dvec2(0);
    box_high_ = glm::dvec2(f.cols, f.rows);
    for (size_t k = 0; k < scene_.boreholes.size(); ++k)
        all_overlays_.push_back(uint32_t(k));
    for (size_t k = 0; k < scene_.fence.size(); ++k)
        all_overlays_.push_back(uint32_t(k) | PANEL);
    if (all_overlays_.empty())
        return;
    // each overlay in the lists of the cells it may touch
    std::vector<std::vector<uint32_t>> lists(f.cells());
    for (uint32_t item : all_overlays_) {
        // a curtain's segment, or a borehole's axis widened by its radius
        glm::dvec2 a, b;
        double margin = 0;
        if (item & PANEL) {
            a = scene_.fence[item & ~PANEL].a;
            b = scene_.fence[item & ~PANEL].b;
        }
        else {
            a = b = glm::dvec2(scene_.boreholes[item].x, scene_.boreholes[item].y);
            margin = scene_.borehole_radius;
        }
        for (uint64_t c : cells_near_segment(f, a, b, margin))
            lists[c].push_back(item);
    }
    if (!scene_.draw_model) {
        // rays need to cross only the cells with overlays
        box_low_ = box_high_;
        box_high_ = glm::dvec2(0);
    }
    overlay_offsets_.assign(f.cells() + 1, 0);
    for (uint64_t c = 0; c < f.cells(); ++c) {
        overlay_items_.insert(overlay_items_.end(), lists[c].begin(), lists[c].end());
        overlay_offsets_[c + 1] = uint32_t(overlay_items_.size());
        if (!lists[c].empty() && !scene_.draw_model) {
            const glm::dvec2 cell(double(c % uint64_t(f.cols)),
                                  double(f.rows - 1 - int(c / uint64_t(f.cols))));
            box_low_ = glm::min(box_low_, cell);
            box_high_ = glm::max(box_high_, cell + 1.0);
        }
    }
}

const std::vector<std::array<glm::dvec3, 2>> &Tracer::overlay_bounds() const
{
    static const std::vector<std::array<glm::dvec3, 2>> none;
    return scene_.draw_model ? none : overlay_boxes_;
}

std::vector<std::array<glm::dvec3, 2>> Tracer::find_overlay_boxes() const
{
    std::vector<std::array<glm::dvec3, 2>> boxes;
    const double low = frame_.corner(0).z, high = frame_.corner(7).z;
    const double r = scene_.borehole_radius;
    for (const Borehole &b : scene_.boreholes) {
        const glm::dvec3 lo(b.x - r, b.y - r, low), hi(b.x + r, b.y + r, high);
        boxes.push_back({lo, glm::dvec3(hi.x, hi.y, borehole_top(b, lo, hi))});
    }
    for (const FencePanel &p : scene_.fence)
        boxes.push_back({glm::dvec3(glm::min(p.a, p.b), low),
                         glm::dvec3(glm::max(p.a, p.b), high)});
    return boxes;
}

double Tracer::borehole_top(const Borehole &b, glm::dvec3 lo, glm::dvec3 hi) const
{
    // the highest a ray can meet in the cylinder's cells: its log, the
    // stack at its axis, the model around it (the hole drilled through it
    // shows the model's walls up to its top); the box's top without the
    // model's pyramid
    const MinMaxPyramid &model = model_pyramid();
    if (model.levels() == 0)
        return hi.z;
    float top = 0;
    for (const std::vector<Interval> *stack : {&b.stack, &b.model_stack})
        if (!stack->empty())
            top = std::max(top, stack->back().top);
    const glm::dvec3 a = frame_.local_from_exaggerated(lo), c = frame_.local_from_exaggerated(hi);
    const auto cell = [](double v, int n) { return std::clamp(int(std::floor(v)), 0, n - 1); };
    const int cols = model.cols(0), rows = model.rows(0);
    for (int y = cell(std::min(a.y, c.y), rows); y <= cell(std::max(a.y, c.y), rows); ++y)
        for (int x = cell(std::min(a.x, c.x), cols); x <= cell(std::max(a.x, c.x), cols); ++x) {
            const ZRange range = model.node(0, x, y);
            if (!range.empty())
                top = std::max(top, range.high);
        }
    // in exaggerated map units, a hundred-thousandth of the box's height
    // higher (no float rounding can put a drawn top above it)
    const double z = frame_.exaggerated_from_map(frame_.map_from_local(glm::dvec3(0, 0, top))).z;
    return std::min(hi.z, z + 1e-5 * (hi.z - lo.z));
}

bool Tracer::cross_borehole(const Borehole &borehole, double t_a, double t_b,
                            const Entry &entry, Walk &walk) const
{
    auto walk_half = [&](const std::vector<Interval> &stack, double a, double b,
                         const Entry &e) {
        return walk_stack(stack.data(), stack.data() + stack.size(), a, b, e, walk);
    };
    if (!scene_.split)
        return walk_half(borehole.stack, t_a, t_b, entry);
    // a split cylinder: the log on the side `split` points to
    const glm::dvec2 s = *scene_.split;
    const glm::dvec2 q(walk.ray.origin.x - borehole.x, walk.ray.origin.y - borehole.y);
    const glm::dvec2 d(walk.ray.direction);
    const double s0 = glm::dot(q, s), s1 = glm::dot(d, s);
    auto stack_at = [&](double t) -> const std::vector<Interval> & {
        return s0 + t * s1 >= 0 ? borehole.stack : borehole.model_stack;
    };
    const double t_split = s1 != 0 ? -s0 / s1 : INF;
    if (!(t_split > t_a && t_split < t_b))
        return walk_half(stack_at((t_a + t_b) / 2), t_a, t_b, entry);
    if (walk_half(stack_at((t_a + t_split) / 2), t_a, t_split, entry))
        return true;
    const glm::dvec3 n(s1 > 0 ? -s : s, 0);
    return walk_half(stack_at((t_split + t_b) / 2), t_split, t_b,
                     {Face::split, n});
}


void Tracer::overlay_events(const uint32_t *first, const uint32_t *last,
                            double t_lo, double t_hi, const Walk &walk,
                            std::vector<Event> &events) const
{
    const glm::dvec2 o(walk.ray.origin), d(walk.ray.direction);
    for (const uint32_t *i = first; i != last; ++i) {
        const uint32_t item = *i;
        if (item & PANEL) {
            double t;
            glm::dvec2 n;
            if (ray_panel(o, d, scene_.fence[item & ~PANEL], t, n) && t >= t_lo &&
                t < t_hi)
                events.push_back({t, t, item, glm::dvec3(n, 0)});
            continue;
        }
        const Borehole &b = scene_.boreholes[item];
        double t0, t1;
        if (!ray_cylinder(o, d, {b.x, b.y}, scene_.borehole_radius, t0, t1) ||
            t1 <= t_lo || t0 >= t_hi)
            continue;
        // the mantle's normal where the ray enters it in this stretch
        const glm::dvec3 n =
            t0 >= t_lo ? glm::dvec3(glm::normalize(o + t0 * d - glm::dvec2(b.x, b.y)), 0)
                       : glm::dvec3(0);
        events.push_back({std::max(t0, t_lo), std::min(t1, t_hi), item, n});
    }
    std::sort(events.begin(), events.end(),
              [](const Event &a, const Event &b) { return a.start < b.start; });
}

uint64_t Tracer::cell_at(glm::dvec3 local) const
{
    const Frame &f = model_.frame();
    const int col = std::clamp(int(std::floor(local.x)), 0, f.cols - 1);
    const int row = f.rows - 1 - std::clamp(int(std::floor(local.y)), 0, f.rows - 1);
    return model_.cell_index(row, col);
}



bool Tracer::cross_events(const std::vector<Event> &events, double t_in,
                          double t_out, Entry entry,
                          const std::vector<Interval> *model_stack, Walk &walk) const
{
    // the model's stack between the overlays, if drawn
    const bool model = model_stack != nullptr;
    const Interval *first = model ? model_stack->data() : nullptr;
    const Interval *last = model ? first + model_stack->size() : nullptr;
    double cursor = t_in;
    for (const Event &e : events) {
        const bool panel = (e.item & PANEL) != 0;
        if (panel ? e.start < cursor : e.end <= cursor)
            continue; // inside a cylinder already crossed
        if (model && e.start > cursor &&
            walk_stack(first, last, cursor, e.start, entry, walk))
            return true;
        if (panel) {
            // the class of the model at the curtain's point
            const glm::dvec3 p = walk.o + e.start * walk.d;
            std::vector<Interval> below_curtain;
            if (!model)
                below_curtain = model_.stack_intervals(cell_at(p));
            const Interval *stack_first = model ? first : below_curtain.data();
            const Interval *stack_last =
                model ? last : below_curtain.data() + below_curtain.size();
            const Interval *k = std::upper_bound(
                stack_first, stack_last, p.z,
                [](double v, const Interval &iv) { return v < double(iv.top); });
            entry = {Face::fence, e.normal, -1};
            if (k != stack_last && meet(k->material, e.start, e.start, entry, walk))
                return true;
            cursor = e.start;
            continue;
        }
        const double start = std::max(e.start, cursor);
        const Entry side = start == e.start && glm::length(e.normal) > 0
                               ? Entry{Face::cylinder, e.normal, -1}
                               : entry;
        const Borehole &b = scene_.boreholes[e.item];
        if (cross_borehole(b, start, e.end, side, walk))
            return true;
        cursor = e.end;
        // leaving the cylinder into the model: its mantle, seen from inside
        const glm::dvec2 at = glm::dvec2(walk.ray.origin) +
                              cursor * glm::dvec2(walk.ray.direction) -
                              glm::dvec2(b.x, b.y);
        entry = {Face::cylinder, glm::dvec3(-glm::normalize(at), 0), -1};
    }
    return model && cursor < t_out && walk_stack(first, last, cursor, t_out, entry, walk);
}

bool Tracer::cross_overlays(uint64_t cell, double t_in, double t_out,
                            const Entry &entry, Walk &walk) const
{
    std::vector<Event> events;
    overlay_events(overlay_items_.data() + overlay_offsets_[cell],
                   overlay_items_.data() + overlay_offsets_[cell + 1], t_in, t_out,
                   walk, events);
    if (!scene_.draw_model)
        return cross_events(events, t_in, t_out, entry, nullptr, walk);
    if (events.empty()) { // the overlays of this cell miss the ray
        const StackRange stack = model_.stack(cell);
        return t_in < t_out && model_.intervals().visit([&](const auto *records) {
            return walk_stack(records + stack.begin, records + stack.end, t_in, t_out,
                              entry, walk);
        });
    }
    const std::vector<Interval> stack = model_.stack_intervals(cell);
    return cross_events(events, t_in, t_out, entry, &stack, walk);
}

} // namespace sbrt
