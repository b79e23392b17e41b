// The tiles of a band that the boreholes' pass draws (shade.comp with
// SBRT_TILE_LIST), listed on the GPU: one work group a box (a borehole's
// bounds, sbrt::make_gpu_boxes). A tile of 8 x 8 pixels is listed where
// the convex hull of the box's eight projected corners meets the tile's
// pixel centres one pixel wider, as sbrt::overlay_tiles lists them on the
// host: separated on no axis of the image and no normal of a line through
// two corners (the hull's edges are among them). A tile's first box lists
// the tile and counts it in the dispatch's work groups; each box goes into
// the tile's slots, or past them only into its count (the pass then tests
// every box there). The head (sbrt::GpuTileHead) is the host's; the
// counts start at 0. A tile whose model hits (the model pass's, just
// done) all lie before the least t at which a ray enters the box is not
// listed for it: every pixel there keeps the model pass's colour.

layout(local_size_x = 64) in;

layout(std430, binding = 12) buffer Tiles { uint tiles[]; };
layout(std430, binding = 13) readonly buffer HitTs { float hit_ts[]; };
layout(std430, binding = 14) readonly buffer Boxes { float boxes[]; };

const uint GROUPS = 0u, SLOTS = 3u, TILE_COLS = 4u, TILE_ROWS = 5u, LIST_AT = 7u,
           COUNTS_AT = 8u, SLOTS_AT = 9u, PIXEL_ROWS = 12u, CAMERA_HI = 24u, CAMERA_LO = 28u,
           RAY_T = 32u, FAR_AT = 36u;
// beyond float rounding of the corners' pixel positions (the tiles are
// already one pixel wider than their centres), and a share of their size
const float MARGIN = 1e-2, ROUNDING = 5e-7;

shared vec2 corner[8];
shared bool in_front[8];
// each corner's t on the ray through it, and a bound on its rounding
shared vec2 corner_t[8];
// per line through two corners: its unit normal and the corners' extent on it
shared vec4 axis[28];

float head_float(uint word) { return uintBitsToFloat(tiles[word]); }

// common/clip.glsl's margin for float rounding around a ray's t (the
// boreholes' pass tests each pixel's model hit against its boxes with it)
float t_margin(float t) { return 1e-4 * abs(t) + 1e-3; }

void list_tile(uint tx, uint ty, uint box)
{
    uint tile = ty * tiles[TILE_COLS] + tx;
    uint n = atomicAdd(tiles[tiles[COUNTS_AT] + tile], 1u);
    if (n == 0u)
        tiles[tiles[LIST_AT] + atomicAdd(tiles[GROUPS], 1u)] = tx | ty << 16;
    if (n < tiles[SLOTS])
        tiles[tiles[SLOTS_AT] + tile * tiles[SLOTS] + n] = box;
}

// Corner `me` of `box` (me < 8): its pixel position, whether it lies in
// front of the camera, its t on the ray through it and a bound on its
// rounding.
void project_corner(uint box, uint me)
{
    vec3 p = vec3(boxes[6u * box + ((me & 1u) != 0u ? 3u : 0u)],
                  boxes[6u * box + 1u + ((me & 2u) != 0u ? 3u : 0u)],
                  boxes[6u * box + 2u + ((me & 4u) != 0u ? 3u : 0u)]);
    vec3 hi = vec3(head_float(CAMERA_HI), head_float(CAMERA_HI + 1u),
                   head_float(CAMERA_HI + 2u));
    vec3 lo = vec3(head_float(CAMERA_LO), head_float(CAMERA_LO + 1u),
                   head_float(CAMERA_LO + 2u));
    vec3 v = (p - hi) - lo;
    vec3 at;
    for (uint k = 0u; k < 3u; ++k) {
        uint row = PIXEL_ROWS + 4u * k;
        at[k] = dot(vec3(head_float(row), head_float(row + 1u), head_float(row + 2u)), v) +
                head_float(row + 3u);
    }
    corner[me] = at.xy / at.z;
    vec3 a = vec3(head_float(RAY_T), head_float(RAY_T + 1u), head_float(RAY_T + 2u));
    float c = head_float(RAY_T + 3u);
    corner_t[me] = vec2(dot(a, v) + c, dot(abs(a), abs(v)) + abs(c));
    // a corner beyond float's range: as if behind (every tile)
    in_front[me] = at.z > 0.0 && !any(isinf(corner[me])) && !any(isnan(corner[me]));
}

// Line `me` of the 28 through two corners (me < 28): its unit normal and
// the corners' extent on it; one that separates nothing where the corners
// are not all in `front` or the two coincide.
void hull_axis(uint me, uint front)
{
    // pair me of the 28 (i < j)
    uint i = 0u, k = me;
    while (k >= 7u - i) {
        k -= 7u - i;
        i += 1u;
    }
    uint j = i + 1u + k;
    vec2 e = corner[j] - corner[i];
    vec2 n = vec2(-e.y, e.x);
    float len = length(n);
    vec4 a = vec4(0.0, 0.0, -1.0 / 0.0, 1.0 / 0.0); // separates nothing
    if (len > 1e-6 && front == 8u) {
        a = vec4(n / len, 1.0 / 0.0, -1.0 / 0.0);
        for (uint k = 0u; k < 8u; ++k) {
            float d = dot(a.xy, corner[k]);
            a.z = min(a.z, d);
            a.w = max(a.w, d);
        }
    }
    axis[me] = a;
}

// The least t of a ray in the box, less what rounding and the boreholes'
// pass's own margin (common/clip.glsl's t_margin) may take away.
float box_least_t()
{
    float t_box = 1.0 / 0.0, t_scale = 0.0;
    for (uint k = 0u; k < 8u; ++k) {
        t_box = min(t_box, corner_t[k].x);
        t_scale = max(t_scale, corner_t[k].y);
    }
    return t_box - (1e-5 * t_scale + t_margin(t_box));
}

// The first and last tile (x, y) of the box's bounds widened by `margin`;
// a box partly behind (float rounding at the camera's plane, the host
// found none): every tile of the band.
vec4 tile_range(uint front, float margin)
{
    vec2 tiles_2d = vec2(float(tiles[TILE_COLS]), float(tiles[TILE_ROWS]));
    if (front < 8u)
        return vec4(vec2(0.0), tiles_2d - 1.0);
    vec2 lo = vec2(1.0 / 0.0), hi = vec2(-1.0 / 0.0);
    for (uint k = 0u; k < 8u; ++k) {
        lo = min(lo, corner[k]);
        hi = max(hi, corner[k]);
    }
    // tile t's centres, one pixel wider: [8 t - 1, 8 t + 8]
    return vec4(clamp(ceil((lo - 8.0 - margin) / 8.0), vec2(0.0), tiles_2d),
                clamp(floor((hi + 1.0 + margin) / 8.0), vec2(-1.0), tiles_2d - 1.0));
}

// Whether an axis of the hull separates tile (tx, ty) from it.
bool tile_apart(uint tx, uint ty, float margin)
{
    vec2 r0 = vec2(8.0 * float(tx) - 1.0, 8.0 * float(ty) - 1.0) - margin;
    vec2 r1 = r0 + 9.0 + 2.0 * margin;
    for (uint a = 0u; a < 28u; ++a) {
        vec4 s = axis[a];
        // the rectangle's extent on the axis
        float low = s.x * (s.x > 0.0 ? r0.x : r1.x) + s.y * (s.y > 0.0 ? r0.y : r1.y);
        float high = s.x * (s.x > 0.0 ? r1.x : r0.x) + s.y * (s.y > 0.0 ? r1.y : r0.y);
        if (high < s.z - margin || low > s.w + margin)
            return true;
    }
    return false;
}

void main()
{
    uint box = gl_WorkGroupID.x, me = gl_LocalInvocationIndex;
    if (me < 8u)
        project_corner(box, me);
    barrier();
    uint front = 0u;
    for (uint k = 0u; k < 8u; ++k)
        front += in_front[k] ? 1u : 0u;
    if (front == 0u)
        return; // wholly behind the camera: no ray goes there
    if (me < 28u)
        hull_axis(me, front);
    barrier();
    float size = 0.0;
    for (uint k = 0u; k < 8u; ++k)
        size = max(size, abs(corner[k].x) + abs(corner[k].y));
    float margin = MARGIN + ROUNDING * size;
    float t_box = box_least_t();
    vec4 range = tile_range(front, margin);
    if (range.z < range.x || range.w < range.y)
        return;
    uint x0 = uint(range.x), y0 = uint(range.y), cols = uint(range.z) - x0 + 1u;
    uint count = cols * (uint(range.w) - y0 + 1u);
    for (uint k = me; k < count; k += 64u) {
        uint tx = x0 + k % cols, ty = y0 + k / cols;
        if (tile_apart(tx, ty, margin))
            continue;
        // the model pass's hits all before the box (behind the camera: a
        // box partly there is listed everywhere)
        float t_far = hit_ts[tiles[FAR_AT] + ty * tiles[TILE_COLS] + tx];
        if (front < 8u || !(t_far + t_margin(t_far) < t_box))
            list_tile(tx, ty, box);
    }
}
