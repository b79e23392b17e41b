/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Normals from the depth image: the hybrid image-space kernel of
 *            Graciano et al. (2018), section 4.1.2, and Gaussian smoothing;
 *            per pixel, so that a whole image (the reference) and a window
 *            of rows (the streamed renderer) give the same normals
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_KERNEL_NORMALS_HPP
#define SBRT_KERNEL_NORMALS_HPP

#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "tracing/hit_image.hpp"

namespace sbrt {

/// \brief The hybrid image-space kernel of one camera.
///
/// A k x k x k grid of voxel-sized cells is centred on the hit point. A cell
/// centre is empty when it lies in front of the surface seen where it
/// projects (or that pixel sees nothing), occupied when it lies behind it;
/// centres on the surface (within a twentieth of a voxel) or outside the
/// image do not count. The surface's depth where a centre projects is its
/// pixel's, moved along the depth's slope to the centre's point within the
/// pixel: the slope of the smoother side across and down (a step's edge is
/// not a slope, nor is a crease), of the reciprocal depth in perspective
/// (affine over the image on a plane). So the centres on a flat top's own
/// level count neither way, as they should, instead of by where in their
/// pixels they fall (a blotchy top). The normal is the sum of the unit
/// vectors towards the empty centres in voxel steps (the paper's cubic
/// voxels), taken to map space (divided by the voxel's sides: a normal
/// transforms by the inverse of the scaling) and normalised. Summed in map
/// space instead, the cells beside the centre of a flat voxel (100 m x
/// 100 m x 10 m: GeoTOP at zexag=20) point nearly sideways and a step of
/// one level in the kernel tilts a flat top by tens of degrees (issue 51,
/// item 6). The face normal stays where the kernel finds no empty centre.
class KernelNormals {
public:
    /// `k` odd, 3..11; `camera` the whole image (not a window of it).
    KernelNormals(const Tracer &tracer, const Camera &camera, int k);

    /// Depth along the view axis of the surface a hit shows (inf: a miss);
    /// what the kernel compares its cells with.
    double view_depth(const Hit &hit) const;

    /// Image rows [first, last) whose depths the kernel reads for the hits
    /// of `hits` (one row of the image, `cols` of them); empty for a row
    /// without hits.
    std::pair<int, int> row_reach(const Hit *hits) const;

    /// The kernel normal of `hit`, seen at depth `depth`; `depth_at(r, c)`
    /// gives view_depth of the hit at pixel (r, c) (rows within row_reach
    /// of the hit's row). Returns false (the face normal stays) where no
    /// cell is empty.
    template <typename DepthAt>
    bool normal(const Hit &hit, double depth, const DepthAt &depth_at,
                glm::vec3 &out) const;

    /// A kernel cell's offset from the centre in the camera's terms.
    struct Cell {
        glm::dvec3 unit; ///< unit vector from the centre, in voxel steps
        double along_du, along_dv, along_forward;
    };
    /// The k^3 - 1 cells around the centre (what the GPU's pass reads).
    const std::vector<Cell> &cells() const { return cells_; }
    /// The depth tolerance's part that does not grow with the depth: a
    /// twentieth of the voxel's least side (exaggerated map units).
    double tolerance_voxel() const { return on_surface_; }
    /// The voxel's sides (exaggerated map units): a sum of cells' unit
    /// vectors divided by them is a map-space normal.
    const glm::dvec3 &voxel() const { return voxel_; }

    /// The depth of the surface seen at pixel (r, c), at (fx, fy) pixels
    /// from its centre (x right, y down, -0.5..0.5).
    template <typename DepthAt>
    double seen_depth(const DepthAt &depth_at, int r, int c, double fx, double fy) const;

private:

    const Tracer &tracer_;
    int rows_, cols_;
    bool parallel_;
    glm::dvec3 origin_, forward_, du_, dv_, voxel_;
    double du2_, dv2_, on_surface_;
    std::vector<Cell> cells_;
    Cell corners_[8]; ///< the extreme cells: their images bound every cell's
};

template <typename DepthAt>
bool KernelNormals::normal(const Hit &hit, double depth, const DepthAt &depth_at,
                           glm::vec3 &out) const
{
    const glm::dvec3 v = tracer_.frame().exaggerated_from_map(hit.point) - origin_;
    const double p_du = glm::dot(v, du_), p_dv = glm::dot(v, dv_);
    const double tolerance = 1e-6 * std::fabs(depth) + on_surface_;
    glm::dvec3 sum(0);
    for (const Cell &cell : cells_) {
        const double z = depth + cell.along_forward;
        double x = (p_du + cell.along_du) / du2_;
        double y = (p_dv + cell.along_dv) / dv2_;
        if (!parallel_) {
            if (!(z > 0))
                continue;
            x /= z;
            y /= z;
        }
        const double at_c = (x + 1) / 2 * cols_, at_r = (1 - y) / 2 * rows_;
        const double c = std::floor(at_c), r = std::floor(at_r);
        if (c < 0 || c >= cols_ || r < 0 || r >= rows_)
            continue;
        if (z < seen_depth(depth_at, int(r), int(c), at_c - c - 0.5, at_r - r - 0.5) -
                    tolerance)
            sum += cell.unit; // in front of the surface: empty
    }
    // from voxel steps to map space (the inverse transpose of the scaling)
    const glm::dvec3 normal = sum / voxel_;
    const double length = glm::length(normal);
    if (!(length > 0))
        return false;
    out = normal / length;
    return true;
}

template <typename DepthAt>
double KernelNormals::seen_depth(const DepthAt &depth_at, int r, int c, double fx,
                                 double fy) const
{
    const double d = depth_at(r, c);
    if (!std::isfinite(d))
        return d; // a miss: anything is in front of it
    // per pixel towards a neighbour at depth n: on a plane the depth of
    // parallel rays moves by n - d, the reciprocal of a perspective one's
    // by a share (d - n) / n of 1 / d (written as differences of depths,
    // which a GPU's floats keep)
    const auto step = [&](double n) { return parallel_ ? n - d : (d - n) / n; };
    // the one-sided step of smaller size, towards +; none across a miss,
    // none at a crease or spike (steps of opposite signs)
    const auto slope = [&](double before, double after) {
        const bool has_back = std::isfinite(before), has_ahead = std::isfinite(after);
        const double back = has_back ? -step(before) : 0;
        const double ahead = has_ahead ? step(after) : 0;
        if (!has_back || !has_ahead)
            return has_back ? back : ahead;
        if (back * ahead <= 0)
            return 0.0;
        return std::fabs(back) < std::fabs(ahead) ? back : ahead;
    };
    const double across = slope(c > 0 ? depth_at(r, c - 1) : INFINITY,
                                c + 1 < cols_ ? depth_at(r, c + 1) : INFINITY);
    const double down = slope(r > 0 ? depth_at(r - 1, c) : INFINITY,
                              r + 1 < rows_ ? depth_at(r + 1, c) : INFINITY);
    const double moved = fx * across + fy * down;
    if (parallel_)
        return d + moved;
    return 1 + moved > 0 ? d / (1 + moved) : INFINITY;
}

/// \brief Separable Gaussian weights of smoothing with `sigma` pixels:
/// 2 radius + 1 of them.
std::vector<double> gaussian_weights(double sigma);

/// Replaces the normal of every hit of a whole image by the kernel
/// estimate (the reference the streamed renderer is tested against).
void apply_kernel_normals(const Tracer &tracer, const Camera &camera, int k,
                          HitImage &hits, unsigned threads = 0);

/// Gaussian smoothing of the normals over the pixels that hit the model.
void smooth_normals(const Camera &camera, double sigma, HitImage &hits,
                    unsigned threads = 0);

} // namespace sbrt

#endif
