// The kernel normal of a hit (KernelNormals::normal) from the view depths
// the depth pass wrote, for the normals pass (kernel_normals.comp) and the
// kernel's shading pass (kernel_shade.comp). After common/kernel.glsl and
// common/shade.glsl (a face's normal: hit_normal).

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
