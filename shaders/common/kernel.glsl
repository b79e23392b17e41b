// What the passes of the image-space kernel normals on the GPU share
// (lib/sbrt/shading/kernel_normals.hpp; the hybrid kernel of Graciano et
// al. 2018, section 4.1.2), over the hit records of the whole image that
// records.comp wrote (SBRT_KERNEL); one entry file a pass:
// - the depth pass (kernel_depth.comp) writes each pixel's view depth;
// - with smoothing (kernel_counts.w, the Gaussian's radius in pixels), the
//   normals pass (kernel_normals.comp) writes each hit's kernel normal and
//   the across pass (kernel_across.comp) their weighted sums along the rows;
// - the shading pass (kernel_shade.comp, SBRT_SHADE) finds the normal of
//   each hit of a band of rows (its kernel normal, or the sum down the
//   columns of the across sums, normalised) and shades the pixel
//   (common/shade.glsl) into the band's outputs.
// A ray that went over the loop budget (llvmpipe) shows nothing to its
// neighbours' kernels, and goes back to the host to be traced there.
// After common/layout.glsl; a hit's kernel normal is
// common/kernel_normal.glsl's.

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
