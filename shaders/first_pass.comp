// The coarse first pass on the GPU (lib/sbrt/tracing/first_hit_bounds.hpp):
// one invocation per tile of SBRT_FIRST_PASS_TILE x SBRT_FIRST_PASS_TILE
// pixels. The rays of a tile form a beam within the box of its corner
// rays (per axis, origin and direction bounds); searching the min-max
// pyramid's nodes nearest first, the first cell the beam enters bounds
// every ray of the tile: none meets anything before. After
// SBRT_FIRST_PASS_BUDGET nodes opened, the nearest node not yet opened
// gives the bound. Bounds are in the rays' t (shade.comp's), pulled back
// well beyond float rounding; inf where the beam meets nothing.

layout(local_size_x = 8, local_size_y = 8) in;

const float INF = 1.0 / 0.0;
const uint HEAP = 4u * uint(SBRT_FIRST_PASS_BUDGET) + 4u;

vec3 o_low = vec3(INF), o_high = vec3(-INF), d_low = vec3(INF), d_high = vec3(-INF);
float s_first = 0.0; // where the rays start (the eye)
// the rounding of the beam's float corners, in cells and local z: node
// boxes are widened by it (the ray casting keeps the origin's high and low
// parts apart, the beam does not)
vec3 slack = vec3(0.0);

// narrows [s0, s1] to where o + s d <= c (below) or >= c (not below)
bool half_line(float o, float d, float c, bool below, inout float s0, inout float s1)
{
    if (d == 0.0)
        return below ? o <= c : o >= c;
    float s = (c - o) / d;
    if ((d > 0.0) == below)
        s1 = min(s1, s);
    else
        s0 = max(s0, s);
    return s0 <= s1;
}

// the first s >= s_first at which the beam may be in the box [low, high]
float enters(vec3 low, vec3 high)
{
    float s0 = s_first, s1 = INF;
    for (int a = 0; a < 3; ++a)
        if (!half_line(o_low[a], d_low[a], high[a], true, s0, s1) ||
            !half_line(o_high[a], d_high[a], low[a], false, s0, s1))
            return INF;
    return s0 <= s1 ? s0 : INF;
}

// the frontier: a binary min-heap on s of (s, level, x, y)
vec4 heap_s_level[HEAP]; // x: s, y: level, z: node x, w: node y
uint heap_count = 0u;

void heap_push(vec4 node)
{
    uint i = heap_count++;
    while (i > 0u) {
        uint parent = (i - 1u) / 2u;
        if (heap_s_level[parent].x <= node.x)
            break;
        heap_s_level[i] = heap_s_level[parent];
        i = parent;
    }
    heap_s_level[i] = node;
}

void heap_pop()
{
    vec4 last = heap_s_level[--heap_count];
    uint i = 0u;
    for (;;) {
        uint child = 2u * i + 1u;
        if (child >= heap_count)
            break;
        if (child + 1u < heap_count && heap_s_level[child + 1u].x < heap_s_level[child].x)
            child += 1u;
        if (last.x <= heap_s_level[child].x)
            break;
        heap_s_level[i] = heap_s_level[child];
        i = child;
    }
    heap_s_level[i] = last;
}

void push(uint level, int x, int y)
{
    uvec4 l = levels[level];
    vec2 range = nodes[l.x + uint(y) * l.y + uint(x)];
    if (range.x > range.y)
        return; // nothing to draw there
    vec3 low = vec3(float(x << level), float(y << level), range.x) - slack;
    vec3 high = vec3(min(float((x + 1) << level), float(grid.x)),
                     min(float((y + 1) << level), float(grid.y)), range.y) + slack;
    float s = enters(low, high);
    if (s < INF && heap_count < HEAP)
        heap_push(vec4(s, float(level), float(x), float(y)));
}

void main()
{
    uvec2 tile = gl_GlobalInvocationID.xy;
    uint image_cols = grid.z, image_rows = grid.w, tile_cols = counts.w;
    uint side = uint(SBRT_FIRST_PASS_TILE);
    uint tile_rows = (image_rows + side - 1u) / side;
    if (tile.x >= tile_cols || tile.y >= tile_rows)
        return;
    // the beam of the tile's corner rays (as trace_pixel makes its rays)
    uint row0 = tile.y * side, col0 = tile.x * side;
    uint row1 = min(row0 + side, image_rows) - 1u, col1 = min(col0 + side, image_cols) - 1u;
    for (int k = 0; k < 4; ++k) {
        uint row = (k & 1) != 0 ? row1 : row0, col = (k & 2) != 0 ? col1 : col0;
        float x = (float(col) + 0.5) / float(image_cols) * 2.0 - 1.0;
        float y = 1.0 - (float(row) + 0.5) / float(image_rows) * 2.0;
        vec3 o = origin_hi.xyz + (origin_lo.xyz + x * spread_u.xyz + y * spread_v.xyz);
        vec3 d = forward.xyz + x * du.xyz + y * dv.xyz;
        o_low = min(o_low, o);
        o_high = max(o_high, o);
        d_low = min(d_low, d);
        d_high = max(d_high, d);
    }
    s_first = spread_u.w;
    // a few float steps of the largest coordinate the beam's origin holds
    vec3 reach = max(abs(o_low), abs(o_high)) + vec3(float(grid.x), float(grid.y), box.x);
    slack = reach * 4.0e-7 + 1.0e-3;
    // best first: the frontier's nearest node bounds every cell below it
    uint top = counts.y - 1u;
    push(top, 0, 0);
    float bound = INF;
    for (uint opened = 0u; heap_count > 0u; ++opened) {
        vec4 node = heap_s_level[0];
        uint level = uint(node.y);
        // (the GPU holds no level below levels[0].w: make_gpu_pyramid)
        if (level <= levels[0].w || opened == uint(SBRT_FIRST_PASS_BUDGET)) {
            bound = node.x;
            break;
        }
        heap_pop();
        uint below = level - 1u;
        uvec4 l = levels[below];
        for (int k = 0; k < 4; ++k) {
            int x = 2 * int(node.z) + (k & 1), y = 2 * int(node.w) + (k >> 1);
            if (uint(x) < l.y && uint(y) < l.z)
                push(below, x, y);
        }
    }
    // pulled back: the beam's corners are floats
    if (bound < INF)
        bound -= 1e-4 * abs(bound) + 1e-2;
    tile_starts[tile.y * tile_cols + tile.x] = bound;
}
