// The kernel normals' depth pass (Pass::kernel_depth): each pixel's view
// depth (common/kernel.glsl).

layout(local_size_x = 8, local_size_y = 8) in;

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
