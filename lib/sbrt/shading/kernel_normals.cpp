/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Image-space kernel normals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/kernel_normals.hpp"

#include <algorithm>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

KernelNormals::KernelNormals(const Tracer &tracer, const Camera &camera, int k)
    : tracer_(tracer), rows_(camera.rows()), cols_(camera.cols()),
      parallel_(camera.parallel()), origin_(camera.origin()),
      forward_(camera.forward()), du_(camera.du()), dv_(camera.dv()),
      voxel_(tracer.frame().voxel_size()), du2_(glm::dot(du_, du_)),
      dv2_(glm::dot(dv_, dv_)),
      on_surface_(0.05 * std::min({tracer.frame().voxel_size().x,
                                   tracer.frame().voxel_size().y,
                                   tracer.frame().voxel_size().z}))
{
    if (k < 3 || k > 11 || k % 2 == 0)
        fail("kernel size ", k, " must be odd, from 3 to 11");
    if (camera.is_window())
        fail("kernel normals need the whole image, not a window of its rows");
    const int h = k / 2;
    auto cell = [&](int a, int b, int c) {
        const glm::dvec3 steps(a, b, c), off = steps * voxel_;
        return Cell{glm::normalize(steps), glm::dot(off, du_), glm::dot(off, dv_),
                    glm::dot(off, forward_)};
    };
    for (int a = -h; a <= h; ++a)
        for (int b = -h; b <= h; ++b)
            for (int c = -h; c <= h; ++c)
                if (a || b || c)
                    cells_.push_back(cell(a, b, c));
    for (int i = 0; i < 8; ++i)
        corners_[i] = cell(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
}

double KernelNormals::view_depth(const Hit &hit) const
{
    if (!hit.is_hit())
        return INFINITY;
    return glm::dot(tracer_.frame().exaggerated_from_map(hit.point) - origin_, forward_);
}

std::pair<int, int> KernelNormals::row_reach(const Hit *hits) const
{
    // every cell centre lies in the box of the eight corner cells, and a
    // projection maps a box in front of the camera into the hull of its
    // corners' images: their rows bound the cells' rows
    double y_low = INFINITY, y_high = -INFINITY;
    for (int col = 0; col < cols_; ++col) {
        const Hit &hit = hits[col];
        if (!hit.is_hit())
            continue;
        const glm::dvec3 v = tracer_.frame().exaggerated_from_map(hit.point) - origin_;
        const double p_dv = glm::dot(v, dv_), depth = glm::dot(v, forward_);
        for (const Cell &corner : corners_) {
            const double z = depth + corner.along_forward;
            double y = (p_dv + corner.along_dv) / dv2_;
            if (!parallel_) {
                if (!(z > 0))
                    return {0, rows_}; // the box reaches behind the camera
                y /= z;
            }
            y_low = std::min(y_low, y);
            y_high = std::max(y_high, y);
        }
    }
    if (y_low > y_high)
        return {0, 0};
    // row = floor((1 - y) / 2 * rows), a row of margin for the rounding
    // and one for the slope of the depth (seen_depth's rows above, below)
    const double first = std::floor((1 - y_high) / 2 * rows_) - 2;
    const double last = std::floor((1 - y_low) / 2 * rows_) + 3;
    return {int(std::clamp(first, 0.0, double(rows_))),
            int(std::clamp(last, 0.0, double(rows_)))};
}

std::vector<double> gaussian_weights(double sigma)
{
    const int radius = int(std::ceil(3 * sigma));
    std::vector<double> weight(2 * radius + 1);
    for (int d = -radius; d <= radius; ++d)
        weight[d + radius] = std::exp(-d * d / (2 * sigma * sigma));
    return weight;
}

void apply_kernel_normals(const Tracer &tracer, const Camera &camera, int k,
                          HitImage &hits, unsigned threads)
{
    const KernelNormals kernel(tracer, camera, k);
    const int rows = camera.rows(), cols = camera.cols();
    std::vector<double> depth(hits.size());
    for (size_t i = 0; i < hits.size(); ++i)
        depth[i] = kernel.view_depth(hits[i]);
    const auto depth_at = [&](int r, int c) { return depth[size_t(r) * cols + c]; };
    // in place: the kernel reads points and depths, never normals
    for_each_row(rows, threads, [&](int row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row) * cols + col;
            if (hits[i].is_hit())
                kernel.normal(hits[i], depth[i], depth_at, hits[i].normal);
        }
    });
}

void smooth_normals(const Camera &camera, double sigma, HitImage &hits,
                    unsigned threads)
{
    if (!(sigma > 0))
        return;
    const int rows = camera.rows(), cols = camera.cols();
    const std::vector<double> weight = gaussian_weights(sigma);
    const int radius = int(weight.size() / 2);
    // separable: along rows, then along columns, over hit pixels only
    auto pass = [&](std::vector<glm::dvec3> &out, const std::vector<glm::dvec3> &in,
                    int step_row, int step_col) {
        for_each_row(rows, threads, [&](int row) {
            for (int col = 0; col < cols; ++col) {
                const size_t i = size_t(row) * cols + col;
                if (!hits[i].is_hit())
                    continue;
                glm::dvec3 sum(0);
                for (int d = -radius; d <= radius; ++d) {
                    const int r = row + d * step_row, c = col + d * step_col;
                    if (r < 0 || r >= rows || c < 0 || c >= cols)
                        continue;
                    const size_t j = size_t(r) * cols + c;
                    if (hits[j].is_hit())
                        sum += weight[d + radius] * in[j];
                }
                out[i] = sum;
            }
        });
    };
    std::vector<glm::dvec3> a(hits.size()), b(hits.size());
    for (size_t i = 0; i < hits.size(); ++i)
        a[i] = hits[i].normal;
    pass(b, a, 0, 1);
    pass(a, b, 1, 0);
    for (size_t i = 0; i < hits.size(); ++i) {
        const double length = glm::length(a[i]);
        if (hits[i].is_hit() && length > 0)
            hits[i].normal = a[i] / length;
    }
}

} // namespace sbrt
