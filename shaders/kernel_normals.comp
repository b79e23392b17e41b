// The kernel normals' normals pass (Pass::kernel_normals, with smoothing):
// each hit's kernel normal (common/kernel_normal.glsl).

layout(local_size_x = 8, local_size_y = 8) in;

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
