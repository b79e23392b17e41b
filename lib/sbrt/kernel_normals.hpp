/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Normals from the depth image: the hybrid image-space kernel of
 *            Graciano et al. (2018), section 4.1.2, and Gaussian smoothing
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_KERNEL_NORMALS_HPP
#define SBRT_KERNEL_NORMALS_HPP

#include <vector>

#include "hit_image.hpp"

namespace sbrt {

/// \brief Replaces the normal of every hit by the kernel estimate.
///
/// A k x k x k grid of voxel-sized cells is centred on the hit point. A cell
/// centre is empty when it lies in front of the surface seen at the pixel it
/// projects to (or that pixel sees nothing), occupied when it lies behind
/// it; centres on the surface or outside the image do not count. The normal
/// is the normalised sum of the unit vectors towards the empty centres. The
/// face normal stays where the kernel finds no empty centre.
void apply_kernel_normals(const Tracer &tracer, const Camera &camera, int k,
                          HitImage &hits, unsigned threads = 0);

/// Gaussian smoothing of the normals over the pixels that hit the model.
void smooth_normals(const Camera &camera, double sigma, HitImage &hits,
                    unsigned threads = 0);

} // namespace sbrt

#endif
