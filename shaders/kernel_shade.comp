// The kernel normals' shading pass (Pass::kernel_shade): each hit of a band
// of rows shaded with its kernel normal, or with smoothing the sum down
// the columns of the across pass's sums (common/kernel.glsl,
// common/kernel_normal.glsl, common/shade.glsl).

layout(local_size_x = 8, local_size_y = 8) in;

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
