// Exact first-hit ray casting of an SBRT: slab clip to the model's box,
// 2D DDA over the cells, and in each cell the z-range the ray covers
// selects the intervals it crosses (the algorithm of lib/sbrt/tracing/tracer.cpp,
// in float).
//
// llvmpipe silently ends a shader invocation after 65,535 loop iterations
// and counts every loop a SIMD vector enters, even with all lanes done.
// So the traversal is ONE loop, a state machine whose every iteration is
// one step: enter a cell, halve the search range of its stack, or walk one
// interval. The loop budget (options.y) bounds it; a ray that would need
// more is flagged, and the host traces it on the CPU. (common/ray.glsl
// holds the ray's state; common/overlays.glsl, where it comes before this
// file, the boreholes and fence curtains.)

layout(local_size_x = 8, local_size_y = 8) in;

uint entry_face(int axis, float d)
{
    if (axis == 0)
        return d > 0.0 ? FACE_WEST : FACE_EAST;
    if (axis == 1)
        return d > 0.0 ? FACE_SOUTH : FACE_NORTH;
    return d > 0.0 ? FACE_BOTTOM : FACE_TOP;
}

// slab clip to [low, high] along one axis: narrows [t_near, t_far]; false
// when the ray runs parallel to the slab outside it
bool clip(int axis, float hi, float lo, float d, float low, float high, inout float t_near,
          inout float t_far, inout int near_axis)
{
    if (d == 0.0) {
        float o = hi + lo;
        return !(o < low || o > high);
    }
    float t0 = from_origin(low, hi, lo) / d;
    float t1 = from_origin(high, hi, lo) / d;
    if (t0 > t1) {
        float s = t0; t0 = t1; t1 = s;
    }
    if (t0 > t_near) {
        t_near = t0;
        near_axis = axis;
    }
    t_far = min(t_far, t1);
    return true;
}

const uint ENTER = 0u, SEARCH = 1u, WALK = 2u, CLIMB = 3u;

vec2 pyramid_node(uint level, int ix, int iy)
{
    uvec4 l = levels[level];
    return nodes[l.x + uint(iy >> level) * l.y + uint(ix >> level)];
}

// whether a ray whose height runs from z_a to z_b stays out of a node's
// range: at or above its top (as the stack walk reads it) or below its
// bottom
bool passes(vec2 range, float z_a, float z_b)
{
    return range.x > range.y || min(z_a, z_b) >= range.y || max(z_a, z_b) < range.x;
}

#ifdef SBRT_HIT_T
// The farthest t of the work group's model hits, for the culling of the
// boreholes' tiles (tile_cull.comp): each pixel's t as a key whose unsigned
// order is the floats' (0: no pixel)
shared uint far_keys[64];

uint far_key(float t)
{
    uint u = floatBitsToUint(t);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

// The tile's farthest t, after the band's pixels' ts (sbrt::GpuTileHead's
// far_at), row by row of tiles
void write_tile_far()
{
    uint most = 0u;
    for (uint k = 0u; k < 64u; ++k)
        most = max(most, far_keys[k]);
    if (most == 0u)
        return;
    uint u = (most & 0x80000000u) != 0u ? most & 0x7fffffffu : ~most;
    uvec2 tile = gl_WorkGroupID.xy;
    hit_ts[options.w * grid.z + tile.y * ((grid.z + 7u) / 8u) + tile.x] = uintBitsToFloat(u);
}
#endif

#ifdef SBRT_SHADE
// The end of the pixel's ray, kept (common/shade.glsl) for
// write_kept_pixel below, or the word that sends it back to the host:
// over the loop budget
void finish(uint index, vec3 point, uint code, float t)
{
#ifdef SBRT_HIT_T
    // -inf: over the budget, the host traces it (the boreholes' pass leaves
    // it alone: listed once); inf: no opaque hit
    float t_hit = (code & CODE_OVER_BUDGET) != 0u ? -1.0 / 0.0
                : (code & 0xffffu) != 0u         ? t
                                                 : 1.0 / 0.0;
    hit_ts[index] = t_hit;
    // over the budget: its tile listed for every box that reaches it
    far_keys[gl_LocalInvocationIndex] = far_key(isinf(t_hit) ? 1.0 / 0.0 : t_hit);
#endif
    if ((code & CODE_OVER_BUDGET) != 0u) {
        send_back(index);
        return;
    }
    keep_pixel(index, point, code, vec3(0.0), t);
}

// The kept end of the pixel's ray (common/shade.glsl), lit along its
// surface's normal and seen through the veil of what the ray crossed
void write_kept_pixel()
{
    if (!kept)
        return;
    vec3 n = ((kept_code >> 16) & 0xfu) < FACE_CYLINDER ? hit_normal(kept_code, ray_d) : kept_n;
    write_pixel(kept_index, kept_point, kept_code, n, vec4(veil, transmittance),
                length((kept_t - t_eye) * ray_d * real_unit.xyz));
}
#else
void finish(uint index, vec3 point, uint code, float t)
{
    hits[index] = PixelHit(point, code, vec4(veil, transmittance));
}
#endif

// Pyramid node of `level` around cell (ix, iy): true where the ray, at
// height z_in when it enters the cell, stays out of the node's range until
// it leaves the node's block (or reaches t_far); then t_exit, exit_axis
// and block describe that block and where the ray leaves it
bool climb(uint level, int ix, int iy, vec3 hi, vec3 lo, vec3 d, float z_in,
           float t_far, inout float t_exit, inout int exit_axis, inout ivec4 block)
{
    vec2 node = pyramid_node(level, ix, iy);
    if (!passes(node, z_in, z_in))
        return false;
    int x0 = (ix >> level) << level, y0 = (iy >> level) << level;
    int x1 = min(x0 + (1 << level), int(grid.x)), y1 = min(y0 + (1 << level), int(grid.y));
    float tx = d.x > 0.0 ? from_origin(float(x1), hi.x, lo.x) / d.x
             : d.x < 0.0 ? from_origin(float(x0), hi.x, lo.x) / d.x
                         : 1.0 / 0.0;
    float ty = d.y > 0.0 ? from_origin(float(y1), hi.y, lo.y) / d.y
             : d.y < 0.0 ? from_origin(float(y0), hi.y, lo.y) / d.y
                         : 1.0 / 0.0;
    float t = min(min(tx, ty), t_far);
    if (!passes(node, z_in, (hi.z + t * d.z) + lo.z))
        return false;
    t_exit = t;
    exit_axis = tx < ty ? 0 : 1; // a tie goes the way the DDA goes
    block = ivec4(x0, y0, x1, y1);
    return true;
}

#ifdef SBRT_TILE_LIST
// A margin for float rounding around a ray's t
float t_margin(float t) { return 1e-4 * abs(t) + 1e-3; }

// Whether the model's pass found the opaque hit of pixel `index` before
// its ray (local: (hi + t d) + lo) enters any box of its tile's boreholes:
// then nothing of them shows there. Else [t_from, t_to] holds where the
// ray is in the boxes and the model pass's hit (t_to inf where that hit may
// be drilled away): with every stratum opaque, outside it the ray meets
// what the model pass found (t_from -inf: no model pass)
bool model_hit_first(uint index, vec3 hi, vec3 lo, vec3 d, out float t_from, out float t_to)
{
    t_from = -1.0 / 0.0;
    t_to = 1.0 / 0.0;
    uint slots = tiles[3];
    if (slots == 0u)
        return false; // no box lists: the camera among them, no model pass
    float t_model = hit_ts[index];
    if (t_model == -1.0 / 0.0)
        return true; // over the model pass's budget: the host traces it
    uvec2 at_tile = work_group_tile();
    uint tile = at_tile.y * tiles[4] + at_tile.x, listed = tiles[tiles[8] + tile];
    // more boxes than slots: every box
    bool every_box = listed > slots;
    uint count = every_box ? tiles[6] : listed;
    float t_entry = 1.0 / 0.0, t_exit = -1.0 / 0.0;
    for (uint k = 0u; k < count; ++k) {
        uint at = 6u * (every_box ? k : tiles[tiles[9] + tile * slots + k]);
        float t0 = -1.0 / 0.0, t1 = 1.0 / 0.0;
        int axis = -1;
        bool met = true;
        for (int a = 0; a < 3 && met; ++a)
            met = clip(a, hi[a], lo[a], d[a], boxes[at + uint(a)], boxes[at + 3u + uint(a)], t0,
                       t1, axis);
        if (met && t0 <= t1) {
            t_entry = min(t_entry, t0);
            t_exit = max(t_exit, t1);
        }
    }
    // no box met, or the model's hit before them (inf: no opaque hit)
    if (isinf(t_entry) || t_model + t_margin(t_model) < t_entry)
        return true;
    float t_in = min(t_entry, t_model);
    t_from = t_in - t_margin(t_in);
    t_to = t_model + t_margin(t_model) < t_exit ? 1.0 / 0.0 : t_exit + t_margin(t_exit);
    return false;
}

// The colour the model's pass packed for pixel (col, row) of the band
uint band_rgb(uint row, uint col)
{
    uint rgb = 0u, base = row * outputs.x;
    for (uint k = 0u; k < 3u; ++k) {
        uint b = col * 3u + k;
        rgb |= ((words[base + b / 4u] >> (8u * (b % 4u))) & 255u) << (8u * k);
    }
    return rgb;
}
#endif

// The first hit of this invocation's pixel, written by finish()
void trace_pixel()
{
    // this dispatch covers the band of image rows from options.z on (its
    // listed tiles in the boreholes' pass)
#ifdef SBRT_SHADE
    uvec2 pixel = work_group_tile() * 8u + gl_LocalInvocationID.xy;
#else
    uvec2 pixel = gl_GlobalInvocationID.xy;
#endif
    uint image_cols = grid.z, image_rows = grid.w, row = pixel.y + options.z;
    if (pixel.x >= image_cols || row >= image_rows || pixel.y >= options.w)
        return;
    uint index = pixel.y * image_cols + pixel.x;
#ifdef SBRT_TEXTURES
    interval_texture_width = uint(textureSize(interval_texture, 0).x);
#endif
    float x = (float(pixel.x) + 0.5) / float(image_cols) * 2.0 - 1.0;
    float y = 1.0 - (float(row) + 0.5) / float(image_rows) * 2.0;

    // rays pass through base + x spread_u + y spread_v, near the model,
    // and start at t_min (the eye): a far camera keeps its precision
    vec3 offset = x * spread_u.xyz + y * spread_v.xyz;
    vec3 hi = origin_hi.xyz, lo = origin_lo.xyz + offset;
    vec3 d = forward.xyz + x * du.xyz + y * dv.xyz;
    float t_min = spread_u.w;
#ifdef SBRT_TILE_LIST
    float t_from, t_to;
    if (model_hit_first(index, hi, lo, d, t_from, t_to)) {
        // what the model's pass wrote stays: its colour to the packing
        group_rgb[gl_LocalInvocationIndex] = band_rgb(pixel.y, pixel.x);
        return;
    }
#endif
    ray_d = d;
    t_eye = t_min;
#ifdef SBRT_BOX_SPANS
    // every stratum opaque: outside [t_from, t_to] the ray meets what the
    // model pass found, whose outputs stay unless a hit in there replaces
    // them
    bool spans = !isinf(t_from);
    if (spans)
        group_rgb[gl_LocalInvocationIndex] = band_rgb(pixel.y, pixel.x);
    else
#endif
    finish(index, vec3(0.0), 0u, 0.0);
#if defined(SBRT_OVERLAYS) || defined(SBRT_BOREHOLES)
    ov_begin(index, hi, lo, d);
#endif

    // 1. slab clip to [0, cols] x [0, rows] x [0, z_max], without a loop
    float t_near = -1.0 / 0.0, t_far = 1.0 / 0.0;
    int near_axis = -1;
    if (!clip(0, hi.x, lo.x, d.x, 0.0, float(grid.x), t_near, t_far, near_axis) ||
        !clip(1, hi.y, lo.y, d.y, 0.0, float(grid.y), t_near, t_far, near_axis) ||
        !clip(2, hi.z, lo.z, d.z, 0.0, box.x, t_near, t_far, near_axis))
        return;
    uint wall = near_axis >= 0 ? entry_face(near_axis, d[near_axis]) : FACE_NONE;
    // clip planes (unrolled by the count, not a loop over a budget):
    // f(t) = a + b t <= 0 is kept
    for (uint k = 0u; k < counts.x; ++k) {
        float a = planes[k].w + dot(planes[k].xyz, offset);
        float b = dot(planes[k].xyz, d);
        if (b == 0.0) {
            if (a > 0.0)
                return;
            continue;
        }
        float t = -a / b;
        if (b > 0.0) {
            t_far = min(t_far, t);
        }
        else if (t > t_near) {
            t_near = t;
            wall = FACE_PLANE | k << 4;
        }
    }
    if (t_near < t_min) {
        t_near = t_min; // the camera is inside the box
        wall = FACE_NONE;
    }
    if (counts.z != 0u) {
        // the first pass: nothing before its tile's bound
        uint side = uint(SBRT_FIRST_PASS_TILE);
        float t_first = tile_starts[(row / side) * counts.w + pixel.x / side];
        if (t_near < t_first) {
            t_near = t_first;
            wall = FACE_NONE;
        }
    }
#ifdef SBRT_BOX_SPANS
    if (spans && t_near < t_from) {
        t_near = t_from;
        wall = FACE_NONE;
    }
    if (spans)
        t_far = min(t_far, t_to);
#endif
    if (!(t_near <= t_far) || box.x <= 0.0)
        return;
#ifdef SBRT_OVERLAYS
    // no model: the boreholes and curtains met directly
    trace_overlays(t_near, t_far, wall);
    return;
#endif

    // 2. 2D DDA; wall distances from the cell index, never accumulated
    int cols = int(grid.x), rows = int(grid.y);
    vec3 p = (hi + t_near * d) + lo;
    int ix = clamp(int(floor(p.x)), 0, cols - 1);
    int iy = clamp(int(floor(p.y)), 0, rows - 1);
    int step_x = d.x > 0.0 ? 1 : -1, step_y = d.y > 0.0 ? 1 : -1;
    float t_in = t_near, t_out = t_near, t_max_x = 0.0, t_max_y = 0.0;
    float z_in = 0.0, z_out = 0.0;
    // exaggerated map length per unit of t, for the translucent strata
    float length_per_t = length(d * box.yzw);
    // WALK visits interval j of [first, last); k is the one holding z_in
    uint mode = ENTER, first = 0u, last = 0u, low = 0u, high = 0u, j = 0u, k = 0u;
    // CLIMB: the pyramid level tried next and the largest block so far that
    // holds nothing at the ray's height: where the ray leaves it, along
    // which axis, and its cells [block.x, block.z) x
    // [block.y, block.w)
    uint level = 0u;
    int exit_axis = -1;
    float t_exit = 0.0;
    ivec4 block = ivec4(0);
    // the block of 2 x 2 cells where the last climb failed: while the ray
    // is in there, it walks the cells without the pyramid (close above
    // material, a climb costs more than it saves)
    int stuck_x = -1, stuck_y = -1;
    // with boreholes (SBRT_BOREHOLES): the loop is left at a cell that
    // holds some, which is crossed out here (common/overlays.glsl), and
    // the loop goes on at the next cell; one small loop for the other cells
    uint work = 0u, budget = options.y;
    bool at_boreholes = false, boreholes_crossed = false;
#ifdef SBRT_BOREHOLES
    // llvmpipe counts the loop's iterations for a SIMD vector whose lanes
    // leave it at different cells: half the budget leaves a margin
    if (budget != 0xffffffffu)
        budget /= 2u;
#endif
    for (;;) {
    for (;; ++work) {
        if (work >= budget) {
            finish(index, vec3(0.0), CODE_OVER_BUDGET, 0.0);
            return;
        }
        bool next_cell = false;
        if (mode == ENTER) {
            t_max_x = d.x != 0.0
                ? from_origin(float(ix + (d.x > 0.0 ? 1 : 0)), hi.x, lo.x) / d.x
                : 1.0 / 0.0;
            t_max_y = d.y != 0.0
                ? from_origin(float(iy + (d.y > 0.0 ? 1 : 0)), hi.y, lo.y) / d.y
                : 1.0 / 0.0;
            t_out = min(min(t_max_x, t_max_y), t_far);
            z_in = (hi.z + t_in * d.z) + lo.z;
            z_out = (hi.z + t_out * d.z) + lo.z;
            bool stuck = (ix >> 1) == stuck_x && (iy >> 1) == stuck_y;
            if (counts.y > 0u && !stuck && passes(pyramid_node(0u, ix, iy), z_in, z_out)) {
                // nothing here at the ray's height: look for the largest
                // block around that holds nothing at its height either; the
                // first level at once, so that a ray close above material
                // takes one step per cell, as without the pyramid
                if (counts.y > 1u && climb(1u, ix, iy, hi, lo, d, z_in, t_far, t_exit,
                                           exit_axis, block)) {
                    level = 2u;
                    mode = CLIMB;
                    continue;
                }
                stuck_x = ix >> 1;
                stuck_y = iy >> 1;
                next_cell = true;
            }
            else {
                uvec2 stack = stack_range(ix, rows - 1 - iy);
                first = stack.x;
                last = stack.y;
#ifdef SBRT_BOREHOLES
                // a cell with boreholes: crossed out of this loop
                if (!boreholes_crossed &&
                    ov_has_boreholes(uint(rows - 1 - iy) * grid.x + uint(ix))) {
                    at_boreholes = true;
                    break;
                }
#endif
                // nothing to find where the ray stays at or above the stack's
                // top (or its boreholes were crossed)
                if (boreholes_crossed || first == last ||
                    min(z_in, z_out) >= interval_top(last - 1u)) {
                    boreholes_crossed = false;
                    next_cell = true;
                }
                else {
                    low = first;
                    high = last;
                    mode = SEARCH;
                }
            }
        }
        else if (mode == CLIMB) {
            bool climbed = level < counts.y &&
                           climb(level, ix, iy, hi, lo, d, z_in, t_far, t_exit,
                                 exit_axis, block);
            level += 1u;
            if (climbed)
                continue;
            // CLIMB starts once level 1 held a block: jump to the cell
            // beyond the largest block found
            if (t_exit >= t_far)
                break;
            vec3 at = (hi + t_exit * d) + lo;
            if (exit_axis == 0) {
                ix = d.x > 0.0 ? block.z : block.x - 1;
                iy = clamp(int(floor(at.y)), block.y, block.w - 1);
            }
            else {
                iy = d.y > 0.0 ? block.w : block.y - 1;
                ix = clamp(int(floor(at.x)), block.x, block.z - 1);
            }
            t_in = t_exit;
            wall = entry_face(exit_axis, d[exit_axis]);
            if (ix < 0 || ix >= cols || iy < 0 || iy >= rows)
                break;
            mode = ENTER;
            continue;
        }
        else if (mode == SEARCH && low < high) {
            // descending: first top >= z_in (intervals are (bottom, top]);
            // else first top > z_in (intervals are [bottom, top))
            uint mid = (low + high) / 2u;
            float top = interval_top(mid);
            if (d.z < 0.0 ? top < z_in : !(z_in < top))
                low = mid + 1u;
            else
                high = mid;
        }
        else if (mode == SEARCH) {
            k = low;
            j = low;
            mode = WALK;
        }
        else {
            // WALK: the ray crosses interval j from t_enter to t_exit,
            // entering through the wall (j == k), its top (descending) or
            // its bottom (ascending)
            bool down = d.z < 0.0;
            if (!down && (j == last || (j != k && !(interval_top(j - 1u) < z_out)))) {
                next_cell = true; // ascending: out of the cell before j
            }
            else {
                uint material = j != last ? interval_material(j) : 0u;
                if (material != 0u) {
                    float t_enter = t_in;
                    uint face = wall;
                    if (j != k) {
                        float z = down ? interval_top(j) : interval_top(j - 1u);
                        t_enter = from_origin(z, hi.z, lo.z) / d.z;
                        face = down ? FACE_TOP : FACE_BOTTOM;
                    }
                    vec4 look = materials[material];
                    if (look.w < 0.0) {
                        finish(index, (hi + t_enter * d) + lo, material | face << 16, t_enter);
                        return;
                    }
                    float t_exit = t_out;
                    if (down && j > first)
                        t_exit = min(t_out, from_origin(interval_top(j - 1u), hi.z, lo.z) / d.z);
                    else if (!down && d.z != 0.0)
                        t_exit = min(t_out, from_origin(interval_top(j), hi.z, lo.z) / d.z);
                    if (absorb(look, max(t_exit - t_enter, 0.0) * length_per_t)) {
                        finish(index, vec3(0.0), 0u, 0.0);
                        return;
                    }
                }
                // on to the next interval the ray reaches in this cell
                if (down) {
                    if (j == first || !(interval_top(j - 1u) > z_out))
                        next_cell = true;
                    else
                        j -= 1u;
                }
                else if (d.z == 0.0) {
                    next_cell = true;
                }
                else {
                    j += 1u;
                }
            }
        }
        if (!next_cell)
            continue;
        if (t_out >= t_far)
            break;
        if (t_max_x < t_max_y) {
            ix += step_x;
            t_in = t_max_x;
            wall = entry_face(0, d.x);
        }
        else {
            iy += step_y;
            t_in = t_max_y;
            wall = entry_face(1, d.y);
        }
        if (ix < 0 || ix >= cols || iy < 0 || iy >= rows)
            break;
        mode = ENTER;
    }
#ifdef SBRT_BOREHOLES
    if (at_boreholes) {
        // they and the cell's stack between them
        at_boreholes = false;
        uint crossed = ov_cross_cell(uint(rows - 1 - iy) * grid.x + uint(ix), uvec2(first, last),
                                     t_in, t_out, wall, work);
        if (crossed == OV_OVER_BUDGET) {
            finish(index, vec3(0.0), CODE_OVER_BUDGET, 0.0);
            return;
        }
        if (crossed == OV_ENDED)
            return; // its end kept where the walk met it
        boreholes_crossed = true; // on to the next cell
        continue;
    }
#endif
    break;
    }
#ifdef SBRT_BOX_SPANS
    if (!spans)
#endif
    finish(index, vec3(0.0), 0u, 0.0);
}

void main()
{
#ifdef SBRT_SHADE
    // every invocation reaches the barrier: the work group's colours are
    // packed into the band's rows once all are shaded
    group_rgb[gl_LocalInvocationIndex] = 0u;
#ifdef SBRT_HIT_T
    far_keys[gl_LocalInvocationIndex] = 0u;
#endif
    trace_pixel();
    write_kept_pixel(); // where its ray ended: one copy of the shading
    memoryBarrierShared();
    barrier();
#ifdef SBRT_HIT_T
    if (gl_LocalInvocationIndex == 0u)
        write_tile_far();
#endif
    pack_group_rgb(min(options.w, grid.w - options.z), grid.z);
#else
    trace_pixel();
#endif
}
