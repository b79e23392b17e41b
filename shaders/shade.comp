// Exact first-hit ray casting of an SBRT, shaded where each ray ends
// (Pass::shade, and with SBRT_TILE_LIST and SBRT_BOREHOLES the boreholes'
// pass over the tiles listed for it): the band's outputs written as the
// host takes them (common/shade.glsl). The ray's walk is
// common/trace_pixel.glsl's.

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

void main()
{
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
}
