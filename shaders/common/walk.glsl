// The walk of a ray of common/trace_pixel.glsl over the model: a 2D DDA over the
// cells (wall distances from the cell index, never accumulated), the
// pyramid's blocks that hold nothing at the ray's height skipped, and in
// each cell the z-range the ray covers selecting the intervals it crosses
// (the algorithm of lib/sbrt/tracing/tracer.cpp, in float). After
// common/clip.glsl (and common/overlays.glsl where boreholes are drawn
// with the model), before common/trace_pixel.glsl, which calls walk_model.
//
// llvmpipe silently ends a shader invocation after 65,535 loop iterations
// and counts every loop a SIMD vector enters, even with all lanes done.
// So the walk is ONE loop, a state machine whose every iteration is one
// step: enter a cell, climb the pyramid, halve the search range of its
// stack, or walk one interval. The loop budget (options.y) bounds it; a
// ray that would need more is flagged, and the host traces it on the CPU.

// the walk's modes: a cell entered, its stack searched for the interval
// at the ray's height, its intervals walked, the pyramid climbed
const uint ENTER = 0u, SEARCH = 1u, WALK = 2u, CLIMB = 3u;

// what one step of the walk leads to: the next step in the loop, the next
// cell, out of the model (or past t_far), the ray's end found (Walk's
// end_*), a cell with boreholes to cross out of the loop
const uint STEP_ON = 0u, STEP_NEXT_CELL = 1u, STEP_LEFT = 2u, STEP_END = 3u,
           STEP_AT_BOREHOLES = 4u;

// how the walk ended: out of the model (or past t_far); at its end
// (finish() with Walk's end_*); at an end the boreholes' walk kept
const uint WALK_LEFT = 0u, WALK_END = 1u, WALK_KEPT = 2u;

// The state of the walk of the ray (hi + t d) + lo up to t_far
struct Walk {
    vec3 hi, lo, d;
    float t_far;
    int cols, rows;
    // the cell (ix, iy), crossed from t_in to t_out, entered through wall
    // at height z_in, left at z_out; the t of its next walls in x and y
    int ix, iy, step_x, step_y;
    float t_in, t_out, t_max_x, t_max_y, z_in, z_out;
    uint wall;
    // exaggerated map length per unit of t, for the translucent strata
    float length_per_t;
    // WALK visits interval j of [first, last); k is the one holding z_in;
    // SEARCH halves [low, high)
    uint mode, first, last, low, high, j, k;
    // CLIMB: the pyramid level tried next and the largest block so far that
    // holds nothing at the ray's height: where the ray leaves it, along
    // which axis, and its cells [block.x, block.z) x [block.y, block.w)
    uint level;
    int exit_axis;
    float t_exit;
    ivec4 block;
    // the block of 2 x 2 cells where the last climb failed: while the ray
    // is in there, it walks the cells without the pyramid (close above
    // material, a climb costs more than it saves)
    int stuck_x, stuck_y;
    // with boreholes (SBRT_BOREHOLES): the cell's boreholes were crossed
    // out of the loop, which goes on at the next cell
    bool boreholes_crossed;
#ifdef SBRT_COLUMN_PAGES
    // the entered cell's entry in its columns' page (layout.glsl)
    uint column_at;
#endif
    // where the walk ended: finish()'s point, code and t
    vec3 end_point;
    uint end_code;
    float end_t;
};

vec2 pyramid_node(uint level, int ix, int iy)
{
    uvec4 l = levels[level];
    return nodes[l.x + uint(iy >> level) * l.y + uint(ix >> level)];
}

// The first level above the cells that the GPU holds (a model whose
// columns are paged holds none below it; levels[0].w, make_gpu_pyramid)
uint first_block_level() { return max(levels[0].w, 1u); }

// The entered cell's range (its node of level 0)
vec2 cell_range(Walk w)
{
#if defined(SBRT_COLUMN_PAGES)
    return column_range(w.column_at);
#elif defined(SBRT_COLUMN_RANGES)
    return column_ranges[uint(w.rows - 1 - w.iy) * grid.x + uint(w.ix)];
#else
    return pyramid_node(0u, w.ix, w.iy);
#endif
}

// whether a ray whose height runs from z_a to z_b stays out of a node's
// range: at or above its top (as the stack walk reads it) or below its
// bottom
bool passes(vec2 range, float z_a, float z_b)
{
    return range.x > range.y || min(z_a, z_b) >= range.y || max(z_a, z_b) < range.x;
}

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

// The walk of the ray (hi + t d) + lo from t_near, where it enters through
// `wall`, to t_far
Walk walk_start(vec3 hi, vec3 lo, vec3 d, float t_near, float t_far, uint wall)
{
    Walk w;
    w.hi = hi;
    w.lo = lo;
    w.d = d;
    w.t_far = t_far;
    w.cols = int(grid.x);
    w.rows = int(grid.y);
    vec3 p = (hi + t_near * d) + lo;
    w.ix = clamp(int(floor(p.x)), 0, w.cols - 1);
    w.iy = clamp(int(floor(p.y)), 0, w.rows - 1);
    w.step_x = d.x > 0.0 ? 1 : -1;
    w.step_y = d.y > 0.0 ? 1 : -1;
    w.t_in = t_near;
    w.t_out = t_near;
    w.t_max_x = 0.0;
    w.t_max_y = 0.0;
    w.z_in = 0.0;
    w.z_out = 0.0;
    w.wall = wall;
    w.length_per_t = length(d * box.yzw);
    w.mode = ENTER;
    w.first = w.last = w.low = w.high = w.j = w.k = 0u;
    w.level = 0u;
    w.exit_axis = -1;
    w.t_exit = 0.0;
    w.block = ivec4(0);
    w.stuck_x = -1;
    w.stuck_y = -1;
    w.boreholes_crossed = false;
#ifdef SBRT_COLUMN_PAGES
    w.column_at = 0u;
#endif
    w.end_point = vec3(0.0);
    w.end_code = 0u;
    w.end_t = 0.0;
    return w;
}

// The walk ends at `point` with `code` at `t` (finish()'s arguments)
uint walk_end(inout Walk w, vec3 point, uint code, float t)
{
    w.end_point = point;
    w.end_code = code;
    w.end_t = t;
    return STEP_END;
}

// ENTER, the pyramid's first level holding nothing at the ray's height in
// the cell: the largest block around that holds nothing at its height
// either; the first level at once, so that a ray close above material
// takes one step per cell, as without the pyramid
uint walk_pass_over(inout Walk w)
{
    uint first = first_block_level();
    if (counts.y > first && climb(first, w.ix, w.iy, w.hi, w.lo, w.d, w.z_in, w.t_far,
                                  w.t_exit, w.exit_axis, w.block)) {
        w.level = first + 1u;
        w.mode = CLIMB;
        return STEP_ON;
    }
    w.stuck_x = w.ix >> 1;
    w.stuck_y = w.iy >> 1;
    return STEP_NEXT_CELL;
}

#ifdef SBRT_COLUMN_TOPS
// The cell's stack as its top interval alone (layout.glsl, TOP_STACK), as
// lib/sbrt's Tracer::cross_top_interval reads it: where the ray enters
// above that interval's bottom and stays above it, or meets the interval
// opaque on its way down (no block read); an empty column: nothing. Else
// false: the block's stack.
bool top_interval_stack(inout Walk w, out uvec2 stack)
{
#ifdef SBRT_COLUMN_PAGES
    // (a word the interval, as the atlas's, where compact)
    uint at = w.column_at / (COLUMN_WORDS / 2u);
    bool topped = true;
#define TOPS atlas
#else
    uint at = uint(w.rows - 1 - w.iy) * grid.x + uint(w.ix);
    bool topped = counts.y > 0u; // the pyramid gives the column's top
#define TOPS column_tops
#endif
#ifdef SBRT_COMPACT_INTERVALS
    uint material = compact_material(TOPS[at]);
    float bottom = compact_top(TOPS[at]);
#else
    uint material = TOPS[2u * at];
    float bottom = uintBitsToFloat(TOPS[2u * at + 1u]);
#endif
#undef TOPS
    stack = uvec2(TOP_STACK);
    if (material == 0u)
        return true; // an empty column
    if (!topped || !(w.z_in > bottom))
        return false; // no pyramid to give its top; or it enters below
    // going below the bottom: only where the interval ends the ray there
    if (!(min(w.z_in, w.z_out) > bottom) && !(materials[material].w < 0.0))
        return false;
    top_material = material;
    top_bottom = bottom;
    top_high = cell_range(w).y; // the column's range
    stack = uvec2(bottom == 0.0 ? TOP_STACK + 1u : TOP_STACK, TOP_STACK + 2u);
    return true;
}
#endif

// ENTER, the cell's stack: searched where the ray may meet some of it
uint walk_into_stack(inout Walk w)
{
#ifdef SBRT_COLUMN_TOPS
    uvec2 stack;
    if (!top_interval_stack(w, stack))
        stack = stack_range(w.ix, w.rows - 1 - w.iy);
#else
    uvec2 stack = stack_range(w.ix, w.rows - 1 - w.iy);
#endif
#ifdef SBRT_PAGED
    // its block not on the GPU: the ray is traced again once it is
    if (stack.x == PAGE_MISSING)
        return walk_end(w, vec3(0.0), CODE_OVER_BUDGET, 0.0);
#endif
    w.first = stack.x;
    w.last = stack.y;
#ifdef SBRT_BOREHOLES
    // a cell with boreholes: crossed out of this loop
    if (!w.boreholes_crossed &&
        ov_has_boreholes(uint(w.rows - 1 - w.iy) * grid.x + uint(w.ix)))
        return STEP_AT_BOREHOLES;
#endif
    // nothing to find where the ray stays at or above the stack's top (or
    // its boreholes were crossed)
    if (w.boreholes_crossed || w.first == w.last ||
        min(w.z_in, w.z_out) >= interval_top(w.last - 1u)) {
        w.boreholes_crossed = false;
        return STEP_NEXT_CELL;
    }
    w.low = w.first;
    w.high = w.last;
    w.mode = SEARCH;
    return STEP_ON;
}

// ENTER: where the ray leaves the cell, its heights; then the pyramid or
// the cell's stack
uint walk_enter(inout Walk w)
{
    w.t_max_x = w.d.x != 0.0
        ? from_origin(float(w.ix + (w.d.x > 0.0 ? 1 : 0)), w.hi.x, w.lo.x) / w.d.x
        : 1.0 / 0.0;
    w.t_max_y = w.d.y != 0.0
        ? from_origin(float(w.iy + (w.d.y > 0.0 ? 1 : 0)), w.hi.y, w.lo.y) / w.d.y
        : 1.0 / 0.0;
    w.t_out = min(min(w.t_max_x, w.t_max_y), w.t_far);
    w.z_in = (w.hi.z + w.t_in * w.d.z) + w.lo.z;
    w.z_out = (w.hi.z + w.t_out * w.d.z) + w.lo.z;
#ifdef SBRT_COLUMN_PAGES
    // the cell's columns' page not on the GPU: the ray is traced again
    // once it is
    w.column_at = column_entry(w.ix, w.rows - 1 - w.iy);
    if (w.column_at == PAGE_MISSING)
        return walk_end(w, vec3(0.0), CODE_OVER_BUDGET, 0.0);
#endif
    bool stuck = (w.ix >> 1) == w.stuck_x && (w.iy >> 1) == w.stuck_y;
    if (counts.y > 0u && !stuck && passes(cell_range(w), w.z_in, w.z_out))
        return walk_pass_over(w); // nothing here at the ray's height
    return walk_into_stack(w);
}

// CLIMB: the next level's block, or (CLIMB starts once level 1 held a
// block) a jump to the cell beyond the largest block found
uint walk_climb(inout Walk w)
{
    bool climbed = w.level < counts.y &&
                   climb(w.level, w.ix, w.iy, w.hi, w.lo, w.d, w.z_in, w.t_far, w.t_exit,
                         w.exit_axis, w.block);
    w.level += 1u;
    if (climbed)
        return STEP_ON;
    if (w.t_exit >= w.t_far)
        return STEP_LEFT;
    vec3 at = (w.hi + w.t_exit * w.d) + w.lo;
    if (w.exit_axis == 0) {
        w.ix = w.d.x > 0.0 ? w.block.z : w.block.x - 1;
        w.iy = clamp(int(floor(at.y)), w.block.y, w.block.w - 1);
    }
    else {
        w.iy = w.d.y > 0.0 ? w.block.w : w.block.y - 1;
        w.ix = clamp(int(floor(at.x)), w.block.x, w.block.z - 1);
    }
    w.t_in = w.t_exit;
    w.wall = entry_face(w.exit_axis, w.d[w.exit_axis]);
    if (w.ix < 0 || w.ix >= w.cols || w.iy < 0 || w.iy >= w.rows)
        return STEP_LEFT;
    w.mode = ENTER;
    return STEP_ON;
}

// SEARCH: one halving of [low, high), then the interval found walked;
// descending: first top >= z_in (intervals are (bottom, top]); else first
// top > z_in (intervals are [bottom, top))
void walk_search(inout Walk w)
{
    if (w.low < w.high) {
        uint mid = (w.low + w.high) / 2u;
        float top = interval_top(mid);
        if (w.d.z < 0.0 ? top < w.z_in : !(w.z_in < top))
            w.low = mid + 1u;
        else
            w.high = mid;
        return;
    }
    w.k = w.low;
    w.j = w.low;
    w.mode = WALK;
}

// WALK, interval j of `material` (not empty): the ray crosses it from
// t_enter to t_exit, entering through the wall (j == k), its top
// (descending) or its bottom (ascending); an opaque one ends the walk, a
// translucent one veils what is behind
uint walk_material(inout Walk w, uint material, bool down)
{
    float t_enter = w.t_in;
    uint face = w.wall;
    if (w.j != w.k) {
        float z = down ? interval_top(w.j) : interval_top(w.j - 1u);
        t_enter = from_origin(z, w.hi.z, w.lo.z) / w.d.z;
        face = down ? FACE_TOP : FACE_BOTTOM;
    }
    vec4 look = materials[material];
    if (look.w < 0.0)
        return walk_end(w, (w.hi + t_enter * w.d) + w.lo, material | face << 16, t_enter);
    float t_exit = w.t_out;
    if (down && w.j > w.first)
        t_exit = min(w.t_out, from_origin(interval_top(w.j - 1u), w.hi.z, w.lo.z) / w.d.z);
    else if (!down && w.d.z != 0.0)
        t_exit = min(w.t_out, from_origin(interval_top(w.j), w.hi.z, w.lo.z) / w.d.z);
    if (absorb(look, max(t_exit - t_enter, 0.0) * w.length_per_t))
        return walk_end(w, vec3(0.0), 0u, 0.0);
    return STEP_ON;
}

// WALK: interval j, then on to the next interval the ray reaches in this
// cell
uint walk_interval(inout Walk w)
{
    bool down = w.d.z < 0.0;
    if (!down && (w.j == w.last || (w.j != w.k && !(interval_top(w.j - 1u) < w.z_out))))
        return STEP_NEXT_CELL; // ascending: out of the cell before j
    uint material = w.j != w.last ? interval_material(w.j) : 0u;
    if (material != 0u && walk_material(w, material, down) == STEP_END)
        return STEP_END;
    if (down) {
        if (w.j == w.first || !(interval_top(w.j - 1u) > w.z_out))
            return STEP_NEXT_CELL;
        w.j -= 1u;
    }
    else if (w.d.z == 0.0) {
        return STEP_NEXT_CELL;
    }
    else {
        w.j += 1u;
    }
    return STEP_ON;
}

// The DDA's step to the next cell; false where the ray leaves the model
// (or reaches t_far)
bool walk_next_cell(inout Walk w)
{
    if (w.t_out >= w.t_far)
        return false;
    if (w.t_max_x < w.t_max_y) {
        w.ix += w.step_x;
        w.t_in = w.t_max_x;
        w.wall = entry_face(0, w.d.x);
    }
    else {
        w.iy += w.step_y;
        w.t_in = w.t_max_y;
        w.wall = entry_face(1, w.d.y);
    }
    if (w.ix < 0 || w.ix >= w.cols || w.iy < 0 || w.iy >= w.rows)
        return false;
    w.mode = ENTER;
    return true;
}

// The walk's loop, one step an iteration, `work` of them (at most
// `budget`): STEP_LEFT, STEP_END (over the budget: CODE_OVER_BUDGET), or
// STEP_AT_BOREHOLES
uint walk_cells(inout Walk w, inout uint work, uint budget)
{
    for (;; ++work) {
        if (work >= budget)
            return walk_end(w, vec3(0.0), CODE_OVER_BUDGET, 0.0);
        uint step;
        if (w.mode == ENTER)
            step = walk_enter(w);
        else if (w.mode == CLIMB)
            step = walk_climb(w);
        else if (w.mode == SEARCH) {
            walk_search(w);
            step = STEP_ON;
        }
        else
            step = walk_interval(w);
        if (step == STEP_NEXT_CELL) {
            if (!walk_next_cell(w))
                return STEP_LEFT;
        }
        else if (step != STEP_ON)
            return step;
    }
    return STEP_LEFT; // not reached
}

// The walk of `w` over the model: WALK_LEFT, WALK_END (finish() with its
// end_*) or WALK_KEPT. With boreholes (SBRT_BOREHOLES) the loop is left
// at a cell that holds some, which is crossed out here
// (common/overlays.glsl), and the loop goes on at the next cell; one small
// loop for the other cells
uint walk_model(inout Walk w)
{
    uint work = 0u, budget = options.y;
#ifdef SBRT_BOREHOLES
    // llvmpipe counts the loop's iterations for a SIMD vector whose lanes
    // leave it at different cells: half the budget leaves a margin
    if (budget != 0xffffffffu)
        budget /= 2u;
#endif
    for (;;) {
        uint step = walk_cells(w, work, budget);
#ifdef SBRT_BOREHOLES
        if (step == STEP_AT_BOREHOLES) {
            // they and the cell's stack between them
            uint crossed = ov_cross_cell(uint(w.rows - 1 - w.iy) * grid.x + uint(w.ix),
                                         uvec2(w.first, w.last), w.t_in, w.t_out, w.wall, work);
            if (crossed == OV_OVER_BUDGET) {
                walk_end(w, vec3(0.0), CODE_OVER_BUDGET, 0.0);
                return WALK_END;
            }
            if (crossed == OV_ENDED)
                return WALK_KEPT; // its end kept where the walk met it
            w.boreholes_crossed = true; // on to the next cell
            continue;
        }
#endif
        return step == STEP_END ? WALK_END : WALK_LEFT;
    }
    return WALK_LEFT; // not reached
}
