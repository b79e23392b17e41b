// Boreholes and fence curtains on the GPU, as lib/sbrt/tracing/
// tracer_overlays.cpp meets them, in float; before common/walk.glsl and
// common/trace_pixel.glsl and shade.comp, which call them:
// - SBRT_OVERLAYS, the model not drawn (boreholes alone, a fence diagram):
//   every overlay the ray crosses between t_near and t_far, in the order
//   of their starts, without walking the cells (trace_overlays);
// - SBRT_BOREHOLES, boreholes drawn with the model: in a cell that holds
//   some, they and the model's stack between them (ov_cross_cell).
// A curtain shows the model's class at its point; a borehole its log (a
// split cylinder: its log on one side, the model's stack on the other).
// Shaded here only (the surfaces' normals are not in a hit record).

#ifndef SBRT_SHADE
#error "the overlays are shaded on the GPU (SBRT_SHADE)"
#endif

// mirrored by sbrt::GpuOverlayHead and sbrt::GpuOverlay (gpu_overlays.hpp)
struct Overlay {
    vec4 ends;    // local x, y of a panel's ends, or twice a borehole's axis
    uvec4 stacks; // the log's first interval and count (first = PANEL: a
                  // fence panel), the model stack's first and count
};
layout(std430, binding = 9) readonly buffer Overlays {
    vec4 overlay_head;   // x: borehole radius (map units); y: the length a
                         // curtain absorbs as; zw: split direction (map;
                         // 0, 0: whole cylinders)
    vec4 map_unit;       // xy: map units per local x, y
    uvec4 overlay_count; // x: overlays
    Overlay overlays[];
};
struct LogInterval {
    uint material;
    float top; // local z
};
layout(std430, binding = 10) readonly buffer Logs { LogInterval logs[]; };
#ifdef SBRT_BOREHOLES
// each cell's first item (row-major from the north; cells + 1 words), then
// the items: indices of overlays
layout(std430, binding = 11) readonly buffer CellOverlays { uint cell_overlays[]; };
#endif

const uint PANEL = 0xffffffffu;

// the ray of this invocation: local (hi + t d) + lo; work done so far
// against the loop budget (llvmpipe), and where it ends
vec3 ov_hi, ov_lo, ov_d;
uint ov_index, ov_work = 0u, ov_limit = 0u;
float ov_length_per_t = 0.0;

void ov_begin(uint index, vec3 hi, vec3 lo, vec3 d)
{
    ov_hi = hi;
    ov_lo = lo;
    ov_d = d;
    ov_index = index;
    ov_length_per_t = length(d * box.yzw);
    // on llvmpipe, a margin below its limit for the loops a SIMD vector
    // runs for lanes already done
    ov_limit = options.y == 0xffffffffu ? options.y : options.y / 2u;
}

float ov_z(float t) { return (ov_hi.z + t * ov_d.z) + ov_lo.z; }
float ov_t_at(float z) { return from_origin(z, ov_hi.z, ov_lo.z) / ov_d.z; }
// the ray's horizontal origin and direction from local point c, map units
vec2 ov_from(vec2 c) { return ((ov_hi.xy - c) + ov_lo.xy) * map_unit.xy; }
vec2 ov_dir() { return ov_d.xy * map_unit.xy; }

// The end of the walk at t kept for the pixel's outputs (keep_pixel):
// code material | surface << 16, surface as trace_pixel's wall (face |
// plane << 4), n its normal where it is a cylinder, curtain or split face;
// code 0 where a veil ends the walk or nothing was met
void ov_keep(float t, uint code, vec3 n)
{
    keep_pixel(ov_index, (ov_hi + t * ov_d) + ov_lo, code, n, t);
}

// Tracer::meet: true where the walk ends (an opaque hit, or a veil
// nothing shows through: kept)
bool ov_meet(uint material, float t_enter, float t_exit, uint surface, vec3 n)
{
    if (material == 0u)
        return false;
    vec4 look = materials[material];
    if (look.w < 0.0) {
        ov_keep(t_enter, material | surface << 16, n);
        return true;
    }
    float crossed = t_exit > t_enter ? (t_exit - t_enter) * ov_length_per_t : overlay_head.y;
    if (absorb(look, crossed)) {
        ov_keep(0.0, 0u | FACE_NONE << 16, vec3(0.0));
        return true;
    }
    return false;
}

// interval j of the model's intervals or of the logs
float ov_top(bool model, uint j) { return model ? interval_top(j) : logs[j].top; }
uint ov_material(bool model, uint j) { return model ? interval_material(j) : logs[j].material; }

// Tracer::walk_stack over [first, last) of the model's intervals or of the
// logs, from t_a to t_b, entering through `surface`; false where the ray
// passes
bool ov_walk(bool model, uint first, uint last, float t_a, float t_b, uint surface, vec3 n)
{
    float z_a = ov_z(t_a), z_b = ov_z(t_b);
    if (first == last || min(z_a, z_b) >= ov_top(model, last - 1u))
        return false;
    // descending: intervals (bottom, top], the first top >= z_a holds z_a;
    // ascending or level: [bottom, top), the first top > z_a
    bool down = ov_d.z < 0.0;
    uint low = first, high = last;
    while (low < high) {
        uint mid = (low + high) / 2u;
        float top = ov_top(model, mid);
        if (down ? top < z_a : !(z_a < top))
            low = mid + 1u;
        else
            high = mid;
        ++ov_work;
    }
    uint k = low;
    if (down) {
        for (uint j = k;; --j) {
            ++ov_work;
            if (j != last) {
                // entered through `surface` (j == k) or its top
                float t_exit = j > first ? min(t_b, ov_t_at(ov_top(model, j - 1u))) : t_b;
                float t_enter = j == k ? t_a : ov_t_at(ov_top(model, j));
                if (ov_meet(ov_material(model, j), t_enter, t_exit, j == k ? surface : FACE_TOP,
                            j == k ? n : vec3(0.0)))
                    return true;
            }
            if (j == first || !(ov_top(model, j - 1u) > z_b))
                return false;
        }
    }
    for (uint j = k; j != last; ++j) {
        ++ov_work;
        if (j != k && !(ov_top(model, j - 1u) < z_b))
            return false;
        // entered through `surface` (j == k) or its bottom
        float t_exit = ov_d.z == 0.0 ? t_b : min(t_b, ov_t_at(ov_top(model, j)));
        float t_enter = j == k ? t_a : ov_t_at(ov_top(model, j - 1u));
        if (ov_meet(ov_material(model, j), t_enter, t_exit, j == k ? surface : FACE_BOTTOM,
                    j == k ? n : vec3(0.0)))
            return true;
        if (ov_d.z == 0.0)
            return false;
    }
    return false;
}

// Tracer::cross_borehole: the cylinder of `o` from t_a to t_b; split (a
// split direction s that the ray crosses in there), in two pieces, the
// second entered through the split face. One walk in the loop: a driver
// that inlines every call compiles it once
bool ov_borehole(Overlay o, float t_a, float t_b, uint surface, vec3 n)
{
    uvec2 log_stack = uvec2(o.stacks.x, o.stacks.x + o.stacks.y);
    uvec2 model_stack = uvec2(o.stacks.z, o.stacks.z + o.stacks.w);
    // the log on the side s points to, the model's stack on the other
    // (whole cylinders, s = 0: the log)
    vec2 s = overlay_head.zw;
    float s0 = dot(ov_from(o.ends.xy), s), s1 = dot(ov_dir(), s);
    float t_split = s1 != 0.0 ? -s0 / s1 : 1.0 / 0.0;
    bool split = s != vec2(0.0) && t_split > t_a && t_split < t_b;
    for (uint piece = 0u; piece < (split ? 2u : 1u); ++piece) {
        float from = piece == 0u ? t_a : t_split, to = split && piece == 0u ? t_split : t_b;
        uvec2 stack = s == vec2(0.0) || s0 + 0.5 * (from + to) * s1 >= 0.0 ? log_stack
                                                                      : model_stack;
        if (ov_walk(false, stack.x, stack.y, from, to, piece == 0u ? surface : FACE_SPLIT,
                    piece == 0u ? n : vec3(s1 > 0.0 ? -s : s, 0.0)))
            return true;
    }
    return false;
}

// Tracer::overlay_events for one overlay: its stretch [start, end] of
// [t_lo, t_hi] (a curtain: a point) and the normal where it starts (0:
// a cylinder entered before t_lo); false where the ray misses it there
bool ov_event(Overlay o, float t_lo, float t_hi, out float start, out float end, out vec3 n)
{
    start = end = 0.0;
    n = vec3(0.0);
    vec2 q = ov_from(o.ends.xy), dd = ov_dir();
    if (o.stacks.x == PANEL) {
        // ray_panel: where the ray crosses the segment
        vec2 e = (o.ends.zw - o.ends.xy) * map_unit.xy;
        float denom = dd.x * e.y - dd.y * e.x;
        if (denom == 0.0)
            return false;
        float t = (-q.x * e.y + q.y * e.x) / denom;
        float u = (-q.x * dd.y + q.y * dd.x) / denom;
        if (!(u >= 0.0 && u <= 1.0) || !(t >= t_lo && t < t_hi))
            return false;
        vec2 normal = normalize(vec2(-e.y, e.x));
        n = vec3(dot(normal, dd) > 0.0 ? -normal : normal, 0.0);
        start = end = t;
        return true;
    }
    // ray_cylinder, from the closest approach (float keeps its precision
    // there, where b^2 - ac would cancel)
    float r = overlay_head.x, a = dot(dd, dd), t0, t1;
    if (a == 0.0) {
        if (!(dot(q, q) < r * r))
            return false;
        t0 = -1.0 / 0.0;
        t1 = 1.0 / 0.0;
    }
    else {
        float t_c = -dot(q, dd) / a;
        vec2 closest = q + t_c * dd;
        float h = (r * r - dot(closest, closest)) / a;
        if (!(h > 0.0))
            return false;
        t0 = t_c - sqrt(h);
        t1 = t_c + sqrt(h);
    }
    if (t1 <= t_lo || t0 >= t_hi)
        return false;
    start = max(t0, t_lo);
    end = min(t1, t_hi);
    if (t0 >= t_lo)
        n = vec3(normalize(q + t0 * dd), 0.0);
    return true;
}

// what a cell with boreholes gave (ov_cross_cell): the ray passes, it
// ended (its end kept) or ran over the loop budget
const uint OV_PASSED = 1u, OV_ENDED = 2u, OV_OVER_BUDGET = 3u;
const uint OV_NONE = 0xffffffffu; // no overlay

// overlay index of item i: every overlay without the model, a cell's list
// with it
#ifdef SBRT_BOREHOLES
uint ov_item(uint i) { return cell_overlays[grid.x * grid.y + 1u + i]; }
#else
uint ov_item(uint i) { return i; }
#endif

// Tracer::cross_events' order: of items [first, end), the overlay met
// next after (last_start, last) within [t_lo, t_hi], ties to the lower
// index; OV_NONE where none is left
uint ov_next(uint first, uint end, float t_lo, float t_hi, float last_start, uint last,
             out float start, out float stop, out vec3 n)
{
    uint best = OV_NONE;
    start = stop = 0.0;
    n = vec3(0.0);
    for (uint i = first; i < end; ++i) {
        uint k = ov_item(i);
        float a, b;
        vec3 normal;
        if (!ov_event(overlays[k], t_lo, t_hi, a, b, normal))
            continue;
        bool later = a > last_start || (a == last_start && k > last);
        if (later && (best == OV_NONE || a < start || (a == start && k < best))) {
            best = k;
            start = a;
            stop = b;
            n = normal;
        }
    }
    ov_work += end - first + 1u;
    return best;
}

// The cylinder of `o` met from `start` (its normal n there, 0 where it
// was entered before) to `stop`, the ray at `cursor` through `surface`:
// true where the walk ends in it; else cursor and surface move to where
// the ray leaves it (its mantle, seen from inside)
bool ov_cross_cylinder(Overlay o, float start, float stop, vec3 n, inout float cursor,
                       inout uint surface, inout vec3 surface_n)
{
    float from = max(start, cursor);
    bool through_mantle = from == start && n != vec3(0.0);
    if (ov_borehole(o, from, stop, through_mantle ? FACE_CYLINDER : surface,
                    through_mantle ? n : surface_n))
        return true;
    cursor = stop;
    surface = FACE_CYLINDER;
    surface_n = vec3(-normalize(ov_from(o.ends.xy) + cursor * ov_dir()), 0.0);
    return false;
}

#ifdef SBRT_OVERLAYS
// Tracer::cross_events without the model: every overlay in the order of
// their starts, each once
void trace_overlays(float t_near, float t_far, uint wall)
{
    uint surface = wall, last = 0u;
    vec3 surface_n = vec3(0.0);
    float cursor = t_near, last_start = -1.0 / 0.0;
    int cols = int(grid.x), rows = int(grid.y);
    for (;;) {
        float start, stop;
        vec3 n;
        uint next = ov_next(0u, overlay_count.x, t_near, t_far, last_start, last, start, stop, n);
        if (ov_work > ov_limit) {
            send_back(ov_index); // over the budget: the host's
            return;
        }
        if (next == OV_NONE)
            break;
        last_start = start;
        last = next;
        Overlay o = overlays[next];
        bool panel = o.stacks.x == PANEL;
        if (panel ? start < cursor : stop <= cursor)
            continue; // inside a cylinder already crossed
        if (!panel) {
            if (ov_cross_cylinder(o, start, stop, n, cursor, surface, surface_n))
                return; // its end kept
            continue;
        }
        // a curtain: the class of the model at its point
        vec3 p = (ov_hi + start * ov_d) + ov_lo;
        uvec2 stack = stack_range(clamp(int(floor(p.x)), 0, cols - 1),
                                  rows - 1 - clamp(int(floor(p.y)), 0, rows - 1));
        uint low = stack.x, high = stack.y;
        while (low < high) {
            uint mid = (low + high) / 2u;
            if (p.z < interval_top(mid))
                high = mid;
            else
                low = mid + 1u;
        }
        surface = FACE_FENCE;
        surface_n = n;
        if (low != stack.y && ov_meet(interval_material(low), start, start, surface, surface_n))
            return; // its end kept
        cursor = start;
    }
    ov_keep(0.0, 0u | FACE_NONE << 16, vec3(0.0)); // no hit: the veil before the background
}
#endif

#ifdef SBRT_BOREHOLES
bool ov_has_boreholes(uint cell) { return cell_overlays[cell] != cell_overlays[cell + 1u]; }

// Tracer::cross_overlays with the model in `cell` (row-major from the
// north; it holds boreholes), crossed from t_in to t_out through `wall`:
// its boreholes in the order of their starts, the model's `stack` between
// them; `work` counts against the loop budget
uint ov_cross_cell(uint cell, uvec2 stack, float t_in, float t_out, uint wall, inout uint work)
{
    uint items_first = cell_overlays[cell], items_last = cell_overlays[cell + 1u];
    ov_work = work;
    uint surface = wall, last = 0u;
    vec3 surface_n = vec3(0.0);
    float cursor = t_in, last_start = -1.0 / 0.0;
    for (;;) {
        float start, stop;
        vec3 n;
        uint next = ov_next(items_first, items_last, t_in, t_out, last_start, last, start, stop, n);
        if (ov_work > ov_limit)
            return OV_OVER_BUDGET;
        if (next != OV_NONE) {
            last_start = start;
            last = next;
            if (stop <= cursor)
                continue; // inside a cylinder already crossed
        }
        // the model's stack up to the next borehole, or to the cell's end
        float to = next != OV_NONE ? start : t_out;
        if (to > cursor && ov_walk(true, stack.x, stack.y, cursor, to, surface, surface_n))
            return OV_ENDED;
        if (next == OV_NONE)
            break;
        if (ov_cross_cylinder(overlays[next], start, stop, n, cursor, surface, surface_n))
            return OV_ENDED;
    }
    work = ov_work;
    return OV_PASSED;
}
#endif
