/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Image-space kernel normals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "kernel_normals.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "error.hpp"
#include "parallel.hpp"

namespace sbrt {

namespace {

/// A kernel cell's offset from the centre in the camera's terms.
struct KernelCell {
    glm::dvec3 unit; ///< unit vector from the centre (map space)
    double along_du, along_dv, along_forward;
};

} // namespace

void apply_kernel_normals(const Tracer &tracer, const Camera &camera, int k,
                          HitImage &hits, unsigned threads)
{
    if (k < 3 || k > 11 || k % 2 == 0)
        fail("kernel size ", k, " must be odd, from 3 to 11");
    if (camera.is_window())
        fail("kernel normals need the whole image, not a window of its rows");
    const int rows = camera.rows(), cols = camera.cols();
    const glm::dvec3 origin = camera.origin(), forward = camera.forward();
    const glm::dvec3 du = camera.du(), dv = camera.dv();
    const double du2 = glm::dot(du, du), dv2 = glm::dot(dv, dv);

    // depth along the view axis of the surface seen at each pixel
    std::vector<double> depth(hits.size(), INFINITY);
    std::vector<glm::dvec3> point(hits.size());
    for (size_t i = 0; i < hits.size(); ++i)
        if (hits[i].is_hit()) {
            point[i] = tracer.exaggerate(hits[i].point);
            depth[i] = glm::dot(point[i] - origin, forward);
        }

    const glm::dvec3 voxel = tracer.voxel_size();
    std::vector<KernelCell> kernel;
    const int h = k / 2;
    for (int a = -h; a <= h; ++a)
        for (int b = -h; b <= h; ++b)
            for (int c = -h; c <= h; ++c) {
                if (!a && !b && !c)
                    continue;
                const glm::dvec3 off = glm::dvec3(a, b, c) * voxel;
                kernel.push_back({glm::normalize(off), glm::dot(off, du),
                                  glm::dot(off, dv), glm::dot(off, forward)});
            }

    for_each_row(rows, threads, [&](int row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row) * cols + col;
            if (!hits[i].is_hit())
                continue;
            const glm::dvec3 v = point[i] - origin;
            const double p_du = glm::dot(v, du), p_dv = glm::dot(v, dv);
            const double p_depth = depth[i];
            const double tolerance = 1e-6 * (std::fabs(p_depth) + voxel.x);
            glm::dvec3 sum(0);
            for (const KernelCell &cell : kernel) {
                const double z = p_depth + cell.along_forward;
                double x = (p_du + cell.along_du) / du2;
                double y = (p_dv + cell.along_dv) / dv2;
                if (!camera.parallel()) {
                    if (!(z > 0))
                        continue;
                    x /= z;
                    y /= z;
                }
                const double c = std::floor((x + 1) / 2 * cols);
                const double r = std::floor((1 - y) / 2 * rows);
                if (c < 0 || c >= cols || r < 0 || r >= rows)
                    continue;
                const double seen = depth[size_t(r) * cols + size_t(c)];
                if (z < seen - tolerance)
                    sum += cell.unit; // in front of the surface: empty
            }
            const double length = glm::length(sum);
            if (length > 0)
                hits[i].normal = sum / length;
        }
    });
}

void smooth_normals(const Camera &camera, double sigma, HitImage &hits,
                    unsigned threads)
{
    if (!(sigma > 0))
        return;
    const int rows = camera.rows(), cols = camera.cols();
    const int radius = int(std::ceil(3 * sigma));
    std::vector<double> weight(2 * radius + 1);
    for (int d = -radius; d <= radius; ++d)
        weight[d + radius] = std::exp(-d * d / (2 * sigma * sigma));
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
