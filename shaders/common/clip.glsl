// Where a ray of common/trace_pixel.glsl enters what it draws and where it stops: the
// slab clip to the model's box, the clip planes, the eye, the first pass's
// bound of its tile; in the boreholes' pass (SBRT_TILE_LIST) the span of
// the ray in its tile's boxes. After common/ray.glsl, before
// common/walk.glsl and common/trace_pixel.glsl, which call them.

// The face a ray enters a cell through when it crosses a wall of `axis`
// going the way of d
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

// The ray (hi + t d) + lo clipped to [0, cols] x [0, rows] x [0, z_max],
// without a loop: [t_near, t_far] and the wall it enters through; false
// where it runs beside the box
bool clip_to_box(vec3 hi, vec3 lo, vec3 d, out float t_near, out float t_far, out uint wall)
{
    t_near = -1.0 / 0.0;
    t_far = 1.0 / 0.0;
    wall = FACE_NONE;
    int near_axis = -1;
    if (!clip(0, hi.x, lo.x, d.x, 0.0, float(grid.x), t_near, t_far, near_axis) ||
        !clip(1, hi.y, lo.y, d.y, 0.0, float(grid.y), t_near, t_far, near_axis) ||
        !clip(2, hi.z, lo.z, d.z, 0.0, box.x, t_near, t_far, near_axis))
        return false;
    wall = near_axis >= 0 ? entry_face(near_axis, d[near_axis]) : FACE_NONE;
    return true;
}

// The clip planes (unrolled by the count, not a loop over a budget):
// f(t) = a + b t <= 0 is kept, of the ray whose origin is the view's
// base + offset; false where the ray runs beside a plane outside it
bool clip_to_planes(vec3 offset, vec3 d, inout float t_near, inout float t_far, inout uint wall)
{
    for (uint k = 0u; k < counts.x; ++k) {
        float a = planes[k].w + dot(planes[k].xyz, offset);
        float b = dot(planes[k].xyz, d);
        if (b == 0.0) {
            if (a > 0.0)
                return false;
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
    return true;
}

// Nothing before the eye t_min, nor, after the first pass, before the
// bound of the tile of pixel (col, row)
void clip_to_start(float t_min, uint row, uint col, inout float t_near, inout uint wall)
{
    if (t_near < t_min) {
        t_near = t_min; // the camera is inside the box
        wall = FACE_NONE;
    }
    if (counts.z != 0u) {
        // the first pass: nothing before its tile's bound
        uint side = uint(SBRT_FIRST_PASS_TILE);
        float t_first = tile_starts[(row / side) * counts.w + col / side];
        if (t_near < t_first) {
            t_near = t_first;
            wall = FACE_NONE;
        }
    }
}

// The ray of pixel (col, row), (hi + t d) + lo with hi + lo the view's base
// + offset, clipped to the model's box, the clip planes and its start:
// [t_near, t_far] and the wall it enters through; false where it misses
bool clip_ray(vec3 hi, vec3 lo, vec3 d, vec3 offset, float t_min, uint row, uint col,
              out float t_near, out float t_far, out uint wall)
{
    if (!clip_to_box(hi, lo, d, t_near, t_far, wall) ||
        !clip_to_planes(offset, d, t_near, t_far, wall))
        return false;
    clip_to_start(t_min, row, col, t_near, wall);
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
#endif
