// Image-space kernel normals on the GPU (lib/sbrt/shading/kernel_normals.hpp;
// the hybrid kernel of Graciano et al. 2018, section 4.1.2), over the hit
// records of the whole image that records.comp wrote (SBRT_KERNEL):
// - the depth pass (SBRT_KERNEL_DEPTH) writes each pixel's view depth;
// - with smoothing (kernel_counts.w, the Gaussian's radius in pixels), the
//   normals pass (SBRT_KERNEL_NORMALS) writes each hit's kernel normal and
//   the across pass (SBRT_KERNEL_ACROSS) their weighted sums along the rows;
// - the shading pass (SBRT_SHADE) finds the normal of each hit of a band of
//   rows (its kernel normal, or the sum down the columns of the across
//   sums, normalised) and shades the pixel (common/shade.glsl) into the
//   band's outputs.
// A ray that went over the loop budget (llvmpipe) shows nothing to its
// neighbours' kernels, and goes back to the host to be traced there.

layout(local_size_x = 8, local_size_y = 8) in;

const float INF = 1.0 / 0.0;

// the pixel of this invocation in the whole image (rows from `first_row`)
// and its index there; false past the image or the rows asked for
bool image_pixel(uint first_row, uint rows_asked, out uvec2 pixel, out uint i)
{
    pixel = uvec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y + first_row);
    i = pixel.y * grid.z + pixel.x;
    return pixel.x < grid.z && pixel.y < grid.w && gl_GlobalInvocationID.y < rows_asked;
}

// whether a record is a hit the kernels see (not a miss, not over budget)
bool seen(PixelHit hit)
{
    return (hit.code & 0xffffu) != 0u && (hit.code & CODE_OVER_BUDGET) == 0u;
}

// the local direction of the ray of pixel (col, row), as trace_pixel's
vec3 pixel_direction(uvec2 pixel, out vec3 start)
{
    float x = (float(pixel.x) + 0.5) / float(grid.z) * 2.0 - 1.0;
    float y = 1.0 - (float(pixel.y) + 0.5) / float(grid.w) * 2.0;
    vec3 d = forward.xyz + x * du.xyz + y * dv.xyz;
    start = (origin_hi.xyz + spread_u.w * d) +
            (origin_lo.xyz + x * spread_u.xyz + y * spread_v.xyz);
    return d;
}

#ifdef SBRT_KERNEL_DEPTH
void main()
{
    uvec2 pixel;
    uint i;
    if (!image_pixel(0u, grid.w, pixel, i))
        return;
    PixelHit hit = image_hits[i];
    // KernelNormals::view_depth: along the view axis from the camera
    depths[i] = seen(hit)
        ? dot(hit.point * kernel_voxel.xyz - kernel_eye.xyz, kernel_forward.xyz) : INF;
}
#elif defined(SBRT_KERNEL_ACROSS)
// KernelBands::smooth, its first pass: along the row, over hits only
void main()
{
    uvec2 pixel;
    uint i;
    if (!image_pixel(0u, grid.w, pixel, i))
        return;
    vec3 sum = vec3(0.0);
    if (kernel_normals[i].w != 0.0) {
        int radius = int(kernel_counts.w), cols = int(grid.z);
        for (int d = -radius; d <= radius; ++d) {
            int c = int(pixel.x) + d;
            if (c >= 0 && c < cols && kernel_normals[i + uint(d)].w != 0.0)
                sum += smoothing_weight(d) * kernel_normals[i + uint(d)].xyz;
        }
    }
    kernel_across[i] = vec4(sum, 0.0);
}
#else
// KernelNormals::seen_depth: the depth seen at pixel (r, c), at (fx, fy)
// pixels from its centre along the smoother side's slope (per pixel
// towards a neighbour at depth n: n - d for parallel rays, the share
// (d - n) / n of 1 / d for perspective ones)
float depth_step(float d, float n)
{
    return kernel_eye.w != 0.0 ? n - d : (d - n) / n;
}

float slope_of(float d, float before, float after)
{
    bool has_back = !isinf(before), has_ahead = !isinf(after);
    float back = has_back ? -depth_step(d, before) : 0.0;
    float ahead = has_ahead ? depth_step(d, after) : 0.0;
    if (!has_back || !has_ahead)
        return has_back ? back : ahead;
    if (back * ahead <= 0.0)
        return 0.0; // a crease or spike
    return abs(back) < abs(ahead) ? back : ahead;
}

float seen_depth(int r, int c, float fx, float fy)
{
    int cols = int(grid.z), rows = int(grid.w);
    float d = depths[uint(r * cols + c)];
    if (isinf(d))
        return d;
    float across = slope_of(d, c > 0 ? depths[uint(r * cols + c - 1)] : INF,
                            c + 1 < cols ? depths[uint(r * cols + c + 1)] : INF);
    float down = slope_of(d, r > 0 ? depths[uint((r - 1) * cols + c)] : INF,
                          r + 1 < rows ? depths[uint((r + 1) * cols + c)] : INF);
    float moved = fx * across + fy * down;
    if (kernel_eye.w != 0.0)
        return d + moved;
    return 1.0 + moved > 0.0 ? d / (1.0 + moved) : INF;
}

// KernelNormals::normal: the unit vectors (in voxel steps) towards the
// kernel's cells that lie in front of the surface seen where they
// project, taken to map space; false (the face normal stays) where none
// does
bool kernel_normal(vec3 point, float depth, out vec3 n)
{
    uint cols = grid.z, rows = grid.w;
    vec3 v = point * kernel_voxel.xyz - kernel_eye.xyz;
    float p_du = dot(v, kernel_du.xyz), p_dv = dot(v, kernel_dv.xyz);
    float tolerance = 1e-6 * abs(depth) + kernel_forward.w;
    bool parallel_rays = kernel_eye.w != 0.0;
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < kernel_counts.x; ++k) {
        vec4 cell = kernel_cells[2u * k], offsets = kernel_cells[2u * k + 1u];
        float z = depth + cell.w;
        float x = (p_du + offsets.x) / kernel_du.w;
        float y = (p_dv + offsets.y) / kernel_dv.w;
        if (!parallel_rays) {
            if (!(z > 0.0))
                continue;
            x /= z;
            y /= z;
        }
        float at_c = (x + 1.0) / 2.0 * float(cols), at_r = (1.0 - y) / 2.0 * float(rows);
        float c = floor(at_c), r = floor(at_r);
        if (c < 0.0 || c >= float(cols) || r < 0.0 || r >= float(rows))
            continue;
        if (z < seen_depth(int(r), int(c), at_c - c - 0.5, at_r - r - 0.5) - tolerance)
            sum += cell.xyz; // in front of the surface: empty
    }
    // from voxel steps to map space (the inverse transpose of the scaling)
    vec3 normal = sum / kernel_voxel.xyz;
    float length_of_normal = length(normal);
    if (!(length_of_normal > 0.0))
        return false;
    n = normal / length_of_normal;
    return true;
}

// the normal of a hit: its kernel normal, else its face's
vec3 hit_kernel_normal(PixelHit hit, uint i, vec3 d)
{
    vec3 n;
    if (!kernel_normal(hit.point, depths[i], n))
        n = hit_normal(hit.code, d);
    return n;
}

#ifdef SBRT_KERNEL_NORMALS
void main()
{
    uvec2 pixel;
    uint i;
    if (!image_pixel(0u, grid.w, pixel, i))
        return;
    PixelHit hit = image_hits[i];
    vec3 start;
    kernel_normals[i] = seen(hit)
        ? vec4(hit_kernel_normal(hit, i, pixel_direction(pixel, start)), 1.0) : vec4(0.0);
}
#else
// KernelBands::smooth, its second pass: down the column over the hits'
// sums along their rows, normalised; the kernel normal where it is zero
vec3 smoothed_normal(uvec2 pixel, uint i)
{
    int radius = int(kernel_counts.w), rows = int(grid.w);
    vec3 sum = vec3(0.0);
    for (int d = -radius; d <= radius; ++d) {
        int r = int(pixel.y) + d;
        uint j = uint(r) * grid.z + pixel.x;
        if (r >= 0 && r < rows && kernel_normals[j].w != 0.0)
            sum += smoothing_weight(d) * kernel_across[j].xyz;
    }
    float length_of_sum = length(sum);
    return length_of_sum > 0.0 ? sum / length_of_sum : kernel_normals[i].xyz;
}

// The kernel normal and outputs of this invocation's pixel
void shade_pixel()
{
    // this dispatch covers the band of image rows from kernel_counts.y on
    uvec2 pixel;
    uint i;
    if (!image_pixel(kernel_counts.y, kernel_counts.z, pixel, i))
        return;
    uint index = gl_GlobalInvocationID.y * grid.z + pixel.x;
    PixelHit hit = image_hits[i];
    if ((hit.code & CODE_OVER_BUDGET) != 0u) {
        flag_over_budget(index);
        return;
    }
    vec3 start;
    vec3 d = pixel_direction(pixel, start), n = vec3(0.0);
    if ((hit.code & 0xffffu) != 0u)
        n = kernel_counts.w > 0u ? smoothed_normal(pixel, i) : hit_kernel_normal(hit, i, d);
    write_pixel(index, hit.point, hit.code, n, hit.veil,
                length((hit.point - start) * real_unit.xyz));
}

void main()
{
    // every invocation reaches the barrier (shade.comp's main)
    group_rgb[gl_LocalInvocationIndex] = 0u;
    shade_pixel();
    memoryBarrierShared();
    barrier();
    pack_group_rgb(min(kernel_counts.z, grid.w - kernel_counts.y), grid.z);
}
#endif
#endif
