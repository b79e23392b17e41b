// Shading of a pixel on the GPU (SBRT_SHADE), as
// lib/sbrt/shading/shading.cpp's PixelShader does it, in float (a colour
// level may differ where the double is within rounding of a half); used by
// the ray casting shader and by the kernel normals' pass (kernel_shade.comp).

#ifdef SBRT_DRAPE
// Drape::on_surface and Texture::sample in the local frame, in float
float drape_surface(int row, int col)
{
    if (row < 0 || row >= int(grid.y) || col < 0 || col >= int(grid.x))
        return -1.0;
    return uintBitsToFloat(drape_words[uint(row) * grid.x + uint(col)]);
}

// whether a hit at local point p through `face` lies on the terrain: on
// the top of a cell's topmost interval, or on a wall between a cell's
// surface and the lower surface of the neighbour it faces
bool on_drape_surface(vec3 p, uint face)
{
    const float EPS = 1e-3; // Drape::SURFACE_EPS
    float u = p.x, v = float(grid.y) - p.y; // columns, rows from the north
    if (face == FACE_TOP) {
        float top = drape_surface(clamp(int(floor(v)), 0, int(grid.y) - 1),
                                  clamp(int(floor(u)), 0, int(grid.x) - 1));
        return top >= 0.0 && abs(p.z - top) <= EPS;
    }
    int row, col, d_row = 0, d_col = 0;
    if (face == FACE_WEST) {
        col = int(floor(u + 0.5)); row = int(floor(v)); d_col = -1;
    } else if (face == FACE_EAST) {
        col = int(floor(u + 0.5)) - 1; row = int(floor(v)); d_col = 1;
    } else if (face == FACE_NORTH) {
        row = int(floor(v + 0.5)); col = int(floor(u)); d_row = -1;
    } else if (face == FACE_SOUTH) {
        row = int(floor(v + 0.5)) - 1; col = int(floor(u)); d_row = 1;
    } else {
        return false;
    }
    float own = drape_surface(row, col), facing = drape_surface(row + d_row, col + d_col);
    return own >= 0.0 && facing >= 0.0 && p.z <= own + EPS && p.z >= facing - EPS;
}

// the texture's colour at local point p (0..255): bilinear over the four
// nearest pixel centres that hold a value; false where none does or p
// lies off the texture
bool drape_sample(vec3 p, out vec3 rgb)
{
    rgb = vec3(0.0);
    int cols = int(drape.y), rows = int(drape.z);
    float u = p.x * drape_map.x + drape_map.y, v = p.y * drape_map.z + drape_map.w;
    if (!(u >= -0.5 && u <= float(cols) - 0.5 && v >= -0.5 && v <= float(rows) - 0.5))
        return false;
    int c0 = int(floor(u)), r0 = int(floor(v));
    float fu = u - float(c0), fv = v - float(r0), weight = 0.0;
    uint texels = grid.x * grid.y;
    for (int k = 0; k < 4; ++k) {
        int dc = k & 1, dr = k >> 1;
        int r = clamp(r0 + dr, 0, rows - 1), c = clamp(c0 + dc, 0, cols - 1);
        uint texel = drape_words[texels + uint(r * cols + c)];
        if ((texel >> 24) == 0u)
            continue;
        float w = (dc == 1 ? fu : 1.0 - fu) * (dr == 1 ? fv : 1.0 - fv);
        rgb += w * vec3(float(texel & 255u), float((texel >> 8) & 255u),
                        float((texel >> 16) & 255u));
        weight += w;
    }
    if (!(weight > 0.0))
        return false;
    rgb /= weight;
    return true;
}
#endif

#ifdef SBRT_PAINT
// The colour entry of voxel `level` of cell (col, row from the north): its
// entry, the none entry (paint_words[3]) outside the grid or the cell's
// span, or GPU_PAINT_OUTSIDE (0xfffe: a value outside the file's stated
// range)
uint paint_entry(int col, int row, int level)
{
    uint entry = paint_words[3];
    if (row < 0 || row >= int(grid.y) || col < 0 || col >= int(grid.x))
        return entry;
    uint cell = uint(row) * grid.x + uint(col);
    uint at = paint_words[4u + 2u * cell], span = paint_words[5u + 2u * cell];
    int lo = int(span & 0xffffu), hi = int(span >> 16);
    if (level < lo || level >= hi)
        return entry;
    uint i = at + uint(level - lo);
    uint e = (paint_words[paint_words[0] + i / 2u] >> (16u * (i & 1u))) & 0xffffu;
    return e == 0xffffu ? entry : e; // GPU_PAINT_NONE
}

#ifdef SBRT_COMPACT_INTERVALS
// Whether the ray of pixel `index` of the band, in double, meets the plane
// of `face` (a cell's wall, top or bottom; its whole-numbered coordinate
// the nearest to q's) inside `voxel`'s face, clear of its edges by far
// more than the double's rounding: then the CPU's tracer, meeting that
// face, finds that voxel. q, voxel: (u, v, z), v in rows from the north.
// Only where every interval's top is a voxel's (compact intervals): a top
// between voxel boundaries is not on that plane, and the CPU finds a
// wall's voxel near such a top from the interval's material.
bool on_face_in_double(uint index, uint face, vec3 q, ivec3 voxel)
{
    const double CLEAR = 1e-7lf;
    int axis = face <= FACE_EAST ? 0 : face <= FACE_NORTH ? 1 : 2;
    uint col = index % grid.z, row = index / grid.z + options.z;
    double x = (double(col) + 0.5) / double(grid.z) * 2.0 - 1.0;
    double y = 1.0 - (double(row) + 0.5) / double(grid.w) * 2.0;
    dvec3 o = exact_origin.xyz + x * exact_spread_u.xyz + y * exact_spread_v.xyz;
    dvec3 d = exact_forward.xyz + x * exact_du.xyz + y * exact_dv.xyz;
    // (u, v, z) of the ray: local x, rows - local y, local z
    o.y = double(grid.y) - o.y;
    d.y = -d.y;
    if (d[axis] == 0.0)
        return false;
    double t = (double(round(q[axis])) - o[axis]) / d[axis];
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        // the rounding of c grows as the ray grazes the plane
        double c = o[a] + t * d[a], clear = CLEAR * max(1.0lf, abs(d[a] / d[axis]));
        if (a != axis && !(c >= double(voxel[a]) + clear && c <= double(voxel[a]) + 1.0lf - clear))
            inside = false;
    }
    return inside;
}
#endif

// The colour (0..255, before lighting) of the voxel a hit at local point
// p through `face` of `material` lies on, as voxel_of_hit
// (lib/sbrt/shading/property_paint.cpp) finds it, for pixel `index` of the
// band. Where a coordinate it floors lies within float's reach of a
// voxel's edge, either voxel may be the hit's: the hit is placed again in
// double (on_face_in_double), else the colour is the voxels' where they
// have the same entry. False where neither settles it, and where the
// value is outside the file's stated range: the host colours those
// pixels.
bool paint_color(uint index, vec3 p, uint face, uint material, out vec3 rgb)
{
    const float EDGE = 1e-4;
    rgb = vec3(0.0);
    float u = p.x, v = float(grid.y) - p.y, z = p.z; // rows from the north
    ivec3 voxel = ivec3(floor(u), floor(v), floor(z));
    if (face == FACE_WEST) voxel.x = int(round(u));
    if (face == FACE_EAST) voxel.x = int(round(u)) - 1;
    if (face == FACE_NORTH) voxel.y = int(round(v));
    if (face == FACE_SOUTH) voxel.y = int(round(v)) - 1;
    if (face == FACE_TOP) voxel.z = int(round(z)) - 1;
    if (face == FACE_BOTTOM) voxel.z = int(round(z));
    // the axes the face does not fix, where the point is near an edge:
    // the voxel across it is the other candidate
    bvec3 free_axis = bvec3(face != FACE_WEST && face != FACE_EAST,
                            face != FACE_NORTH && face != FACE_SOUTH,
                            face != FACE_TOP && face != FACE_BOTTOM);
    vec3 q = vec3(u, v, z);
    ivec3 across = ivec3(0);
    int near_edges = 0;
    for (int a = 0; a < 3; ++a)
        if (free_axis[a] && abs(q[a] - round(q[a])) <= EDGE) {
            // the voxel on the other side of the edge at round(q)
            across[a] = voxel[a] == int(round(q[a])) ? -1 : 1;
            ++near_edges;
        }
    // a cell's face: placed again in double, where it lies well inside
    // the voxel's face that voxel is the CPU's
#ifdef SBRT_COMPACT_INTERVALS
    if (near_edges > 0 && face >= FACE_WEST && face <= FACE_TOP &&
        on_face_in_double(index, face, q, voxel))
        near_edges = 0;
#endif
    if (near_edges > 1)
        return false;
    uint entry = paint_entry(voxel.x, voxel.y, voxel.z);
    if (entry == 0xfffeu) // GPU_PAINT_OUTSIDE
        return false;
    if (near_edges == 1) {
        ivec3 other = voxel + across;
        if (paint_entry(other.x, other.y, other.z) != entry)
            return false;
    }
    uint fades = paint_words[2];
    uint c = paint_words[1] + 3u * (fades == 0u ? entry : material * fades + entry);
    rgb = vec3(uintBitsToFloat(paint_words[c]), uintBitsToFloat(paint_words[c + 1u]),
               uintBitsToFloat(paint_words[c + 2u]));
    return true;
}
#endif

// The normal of a hit from its face (a cell's face, a clip plane's, or
// facing the ray where the camera is in the material; `ray_d` the ray's
// local direction)
vec3 hit_normal(uint code, vec3 ray_d)
{
    uint face = (code >> 16) & 0xfu;
    if (face == FACE_PLANE)
        return plane_normals[(code >> 20) & 0xfu].xyz;
    if (face == FACE_NONE)
        return -normalize(ray_d * box.yzw); // the camera is in the material
    return vec3(face == FACE_WEST ? -1.0 : face == FACE_EAST ? 1.0 : 0.0,
                face == FACE_SOUTH ? -1.0 : face == FACE_NORTH ? 1.0 : 0.0,
                face == FACE_BOTTOM ? -1.0 : face == FACE_TOP ? 1.0 : 0.0);
}

// This work group's colours (r | g << 8 | b << 16), one per invocation,
// packed into the band's RGB rows once all are shaded (pack_group_rgb)
shared uint group_rgb[64];

// The bits of the double of `f` (low word, high word), exactly, without
// fp64 in the shader: the host's sinks take doubles as they are
uvec2 double_bits(float f)
{
    uint bits = floatBitsToUint(f);
    uint sign = bits & 0x80000000u, e = (bits >> 23) & 0xffu, m = bits & 0x7fffffu;
    if (e == 0xffu) // infinity or NaN (its payload kept)
        return uvec2(m << 29, sign | 0x7ff00000u | (m >> 3));
    if (e == 0u) {
        if (m == 0u)
            return uvec2(0u, sign);
        // subnormal, m 2^-149: normalised, 1.f 2^(msb - 149)
        int msb = findMSB(m);
        m = (m << uint(23 - msb)) & 0x7fffffu;
        return uvec2(m << 29, sign | (uint(msb + 874) << 20) | (m >> 3));
    }
    return uvec2(m << 29, sign | ((e + 896u) << 20) | (m >> 3));
}

void write_double(uint at, float f)
{
    uvec2 bits = double_bits(f);
    words[at] = bits.x;
    words[at + 1u] = bits.y;
}

// Pixel `index` of the band is over the loop budget: the host traces it
void flag_over_budget(uint index)
{
    uint n = atomicAdd(words[band_planes.w], 1u);
    if (band_planes.w + 1u + n < uint(words.length())) // (the host checks the count)
        words[band_planes.w + 1u + n] = index;
}

// The outputs of pixel `index` of the band: the colour of the hit (local
// point, code) lit along normal n, seen through the veil (rgb) and
// transmittance (a) of the translucent strata in front; the class id,
// elevation and distance (`depth`, real map units) asked for.
void write_pixel(uint index, vec3 point, uint code, vec3 n, vec4 veil_t, float depth)
{
    uint material = code & 0xffffu;
    vec3 color = background.rgb;
    if (material != 0u) {
#ifdef SBRT_PAINT
        vec3 surface;
        if (!paint_color(index, point, (code >> 16) & 0xfu, material, surface)) {
            flag_over_budget(index); // the host colours it
            group_rgb[gl_LocalInvocationIndex] = 0u;
            return;
        }
#else
        uint rgb = looks[material].x;
        vec3 surface = vec3(float(rgb & 255u), float((rgb >> 8) & 255u),
                            float((rgb >> 16) & 255u));
#endif
#ifdef SBRT_DRAPE
        vec3 texture_rgb;
        if (on_drape_surface(point, (code >> 16) & 0xfu) && drape_sample(point, texture_rgb))
            surface += drape.x * (texture_rgb - surface);
#endif
        // a cut (section, plane, fence curtain) shows its classes as the
        // legend does, whatever the light: a section seen head-on is not
        // in shadow
        uint face = (code >> 16) & 0xfu;
        float lambert = face == FACE_PLANE || face == FACE_FENCE
            ? 1.0 : max(0.0, dot(light.xyz, n));
        color = surface * (light.w + (1.0 - light.w) * lambert);
    }
    color = 255.0 * veil_t.rgb + veil_t.a * color;
    uvec3 c = uvec3(floor(clamp(color, 0.0, 255.0) + 0.5));
    group_rgb[gl_LocalInvocationIndex] = c.r | c.g << 8 | c.b << 16;
    float missing = uintBitsToFloat(0x7fc00000u); // NaN
    if ((outputs.y & 1u) != 0u)
        words[band_planes.x + index] = material != 0u ? looks[material].y : 0x80000000u;
    if ((outputs.y & 2u) != 0u)
        write_double(band_planes.y + 2u * index,
                     material != 0u ? real_unit.w + point.z * elevation_step.x : missing);
    if ((outputs.y & 4u) != 0u)
        write_double(band_planes.z + 2u * index, material != 0u ? depth : missing);
}

// Where the pixel's ray ended, kept by the entry file's finish and the
// overlays' walks and written once after the trace (shade.comp's
// write_kept_pixel): one copy of the shading in the program. A driver that
// inlines every call compiles each copy (NVIDIA's took very long over the
// boreholes' program with a copy at each end: docs/performance.md). Only
// what the end alone knows is kept, and held through the trace's loop: the
// veil, a cell face's normal and the depth are found when written.
bool kept = false;
uint kept_index = 0u, kept_code = 0u;
vec3 kept_point = vec3(0.0), kept_n = vec3(0.0);
float kept_t = 0.0;

// The end of pixel `index`'s ray at t (local point, code); n: the normal
// of a borehole's mantle, a curtain or a split face (FACE_CYLINDER and
// after), the others' found from the code
void keep_pixel(uint index, vec3 point, uint code, vec3 n, float t)
{
    kept = true;
    kept_index = index;
    kept_point = point;
    kept_code = code;
    kept_n = n;
    kept_t = t;
}

// After a barrier, in uniform control flow: the work group's colours into
// its words of the band's RGB rows. Its 8 x 8 pixels start at column
// 8 gx, byte 24 gx of a row: a whole word, so each word of a row has one
// work group; invocation (x, y) writes word x of its row of the group.
// `band_rows`: the rows of this dispatch; `image_cols`: the row's pixels.
void pack_group_rgb(uint band_rows, uint image_cols)
{
    uvec2 group = work_group_tile(), local = gl_LocalInvocationID.xy;
    uint row = group.y * 8u + local.y, first_col = group.x * 8u;
    if (row >= band_rows || first_col >= image_cols)
        return;
    uint pixels = min(8u, image_cols - first_col);
    if (local.x >= (3u * pixels + 3u) / 4u)
        return;
    uint word = 0u;
    for (uint b = 0u; b < 4u; ++b) {
        uint byte_index = 4u * local.x + b, p = byte_index / 3u;
        if (p < pixels)
            word |= ((group_rgb[local.y * 8u + p] >> (8u * (byte_index % 3u))) & 255u)
                    << (8u * b);
    }
    words[row * outputs.x + 6u * group.x + local.x] = word;
}
