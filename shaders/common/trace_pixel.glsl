// The first hit of a pixel's ray (trace_pixel): the ray of this
// invocation's pixel clipped to what it draws (common/clip.glsl) and walked
// over the model's cells and stacks (common/walk.glsl), its end handed to
// finish(), which the program's entry file defines (records.comp: a hit
// record; shade.comp: the pixel kept for its shading). common/ray.glsl
// holds the ray's state; common/overlays.glsl, where it comes before this
// file, the boreholes and fence curtains.

// The entry file's: the end of the pixel's ray at `point` with `code` at `t`
void finish(uint index, vec3 point, uint code, float t);
#ifdef SBRT_TILE_LIST
// shade.comp's: the colour the model's pass packed for pixel (col, row)
uint band_rgb(uint row, uint col);
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
