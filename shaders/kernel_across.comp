// The kernel normals' across pass (Pass::kernel_across, with smoothing):
// the kernel normals' weighted sums along the rows (common/kernel.glsl).

layout(local_size_x = 8, local_size_y = 8) in;

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
