// Exact first-hit ray casting of an SBRT: the ray of this invocation's
// pixel clipped to what it draws (common/clip.glsl) and walked over the
// model's cells and stacks (common/walk.glsl), its end kept or written
// (finish). common/ray.glsl holds the ray's state; common/overlays.glsl,
// where it comes before this file, the boreholes and fence curtains.

layout(local_size_x = 8, local_size_y = 8) in;

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

#ifdef SBRT_TILE_LIST
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

    float t_near, t_far;
    uint wall;
    if (!clip_ray(hi, lo, d, offset, t_min, row, pixel.x, t_near, t_far, wall))
        return;
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

    Walk w = walk_start(hi, lo, d, t_near, t_far, wall);
    uint end = walk_model(w);
    if (end == WALK_END)
        finish(index, w.end_point, w.end_code, w.end_t);
#ifdef SBRT_BOX_SPANS
    else if (end == WALK_LEFT && !spans)
#else
    else if (end == WALK_LEFT)
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
