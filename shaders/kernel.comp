// Image-space kernel normals on the GPU (lib/sbrt/shading/kernel_normals.hpp;
// the hybrid kernel of Graciano et al. 2018, section 4.1.2), over the hit
// records of the whole image that raycast.comp wrote (SBRT_KERNEL):
// - the depth pass (SBRT_KERNEL_DEPTH) writes each pixel's view depth;
// - the shading pass finds the kernel normal of each hit of a band of rows
//   from the depths its kernel cells project to, and shades the pixel
//   (common/shade.glsl) into the band's outputs.
// A ray that went over the loop budget (llvmpipe) shows nothing to its
// neighbours' kernels, and goes back to the host to be traced there.

layout(local_size_x = 8, local_size_y = 8) in;

const float INF = 1.0 / 0.0;

#ifdef SBRT_KERNEL_DEPTH
void main()
{
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uint cols = grid.z, rows = grid.w;
    if (pixel.x >= cols || pixel.y >= rows)
        return;
    uint i = pixel.y * cols + pixel.x;
    PixelHit hit = image_hits[i];
    bool seen = (hit.code & 0xffffu) != 0u && (hit.code & CODE_OVER_BUDGET) == 0u;
    // KernelNormals::view_depth: along the view axis from the camera
    depths[i] = seen ? dot(hit.point * kernel_voxel.xyz - kernel_eye.xyz, kernel_forward.xyz)
                     : INF;
}
#else
// KernelNormals::normal: the unit vectors towards the kernel's cells that
// lie in front of the surface seen where they project; false (the face
// normal stays) where none does
bool kernel_normal(vec3 point, float depth, out vec3 n)
{
    uint cols = grid.z, rows = grid.w;
    vec3 v = point * kernel_voxel.xyz - kernel_eye.xyz;
    float p_du = dot(v, kernel_du.xyz), p_dv = dot(v, kernel_dv.xyz);
    float tolerance = 1e-6 * (abs(depth) + kernel_forward.w);
    bool parallel_rays = kernel_eye.w != 0.0;
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < kernel_counts.x; ++k) {
        vec4 cell = kernel_cells[2u * k], across = kernel_cells[2u * k + 1u];
        float z = depth + cell.w;
        float x = (p_du + across.x) / kernel_du.w;
        float y = (p_dv + across.y) / kernel_dv.w;
        if (!parallel_rays) {
            if (!(z > 0.0))
                continue;
            x /= z;
            y /= z;
        }
        float c = floor((x + 1.0) / 2.0 * float(cols));
        float r = floor((1.0 - y) / 2.0 * float(rows));
        if (c < 0.0 || c >= float(cols) || r < 0.0 || r >= float(rows))
            continue;
        if (z < depths[uint(r) * cols + uint(c)] - tolerance)
            sum += cell.xyz; // in front of the surface: empty
    }
    float length_of_sum = length(sum);
    if (!(length_of_sum > 0.0))
        return false;
    n = sum / length_of_sum;
    return true;
}

void main()
{
    // this dispatch covers the band of image rows from kernel_counts.y on
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uint cols = grid.z, rows = grid.w, row = pixel.y + kernel_counts.y;
    if (pixel.x >= cols || row >= rows || pixel.y >= kernel_counts.z)
        return;
    uint index = pixel.y * cols + pixel.x, i = row * cols + pixel.x;
    PixelHit hit = image_hits[i];
    if ((hit.code & CODE_OVER_BUDGET) != 0u) {
        words[index * outputs.x] = 0u;
        return;
    }
    // the pixel's ray (as raycast.comp makes it) and where it starts
    float x = (float(pixel.x) + 0.5) / float(cols) * 2.0 - 1.0;
    float y = 1.0 - (float(row) + 0.5) / float(rows) * 2.0;
    vec3 d = forward.xyz + x * du.xyz + y * dv.xyz;
    vec3 start = (origin_hi.xyz + spread_u.w * d) +
                 (origin_lo.xyz + x * spread_u.xyz + y * spread_v.xyz);
    vec3 n;
    if ((hit.code & 0xffffu) == 0u || !kernel_normal(hit.point, depths[i], n))
        n = hit_normal(hit.code, d);
    write_pixel(index, hit.point, hit.code, n, hit.veil,
                length((hit.point - start) * real_unit.xyz));
}
#endif
