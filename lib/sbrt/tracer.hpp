/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Exact CPU reference ray caster (double precision): slab clip
 *            to the model's box, 2D DDA over the cells, and in each cell the
 *            z-range the ray covers selects the intervals it crosses
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_TRACER_HPP
#define SBRT_TRACER_HPP

#include <limits>
#include <vector>

#include "camera.hpp"
#include "model.hpp"

namespace sbrt {

/// Face of a hit: which plane of the cell/interval the ray entered through.
enum class Face { none, west, east, south, north, bottom, top, plane };

/// \brief A clip plane in real map coordinates: everything on the side the
/// normal points to is removed (what is left is cut open along the plane).
struct ClipPlane {
    glm::dvec3 point;
    glm::dvec3 normal; ///< not zero; need not be unit length
};

/// Most clip planes one render takes (the GPU's view block holds them).
constexpr int MAX_CLIP_PLANES = 8;

/// Outward unit normal of a cell face (zero for Face::none and a plane).
glm::dvec3 face_normal(Face face);

/// \brief First opaque hit of a ray; t is in map units along the ray.
struct Hit {
    double t = std::numeric_limits<double>::infinity();
    uint32_t material = EMPTY;
    Face face = Face::none;
    int plane = -1; ///< the clip plane hit, with Face::plane
    glm::dvec3 point{0}; ///< real (unexaggerated) map coordinates
    glm::dvec3 normal{0};
    bool is_hit() const { return material != EMPTY; }
};

/// \brief Exact traversal of an SBRT. Rays are in map coordinates with
/// vertical exaggeration `zexag` applied about the model's bottom.
class Tracer {
public:
    Tracer(const Model &model, double zexag, std::vector<ClipPlane> planes = {});

    Hit trace(const Ray &ray) const;

    /// Exaggerated map coordinates of a real map point, and back.
    glm::dvec3 exaggerate(glm::dvec3 p) const;
    glm::dvec3 unexaggerate(glm::dvec3 p) const;
    /// The local frame: x, y in cells from the west and south edges, z in
    /// tb_res steps from the bottom (exaggerated map -> local, and back to
    /// real map coordinates).
    glm::dvec3 to_local(glm::dvec3 exaggerated) const;
    glm::dvec3 local_direction(glm::dvec3 direction) const { return direction * scale_; }
    glm::dvec3 from_local(glm::dvec3 local) const;
    /// Centre and half-diagonal of the model's box (exaggerated).
    glm::dvec3 centre() const;
    double radius() const;
    /// Corner k (0..7, bit 0 east, bit 1 north, bit 2 top) of the model's
    /// box, exaggerated map coordinates.
    glm::dvec3 corner(int k) const;
    /// Top of the highest interval, map units.
    double top_elevation() const;
    /// Size of a voxel in exaggerated map units (ew, ns, tb * zexag).
    glm::dvec3 voxel_size() const { return 1.0 / scale_; }
    /// Top of the highest interval, local units (tb_res steps).
    double top_local() const { return z_max_local_; }
    const Model &model() const { return model_; }

    /// A clip plane in the local frame: f(l) = n . l + c, kept where f <= 0;
    /// `shading_normal` is its unit normal in exaggerated map space.
    struct LocalPlane {
        glm::dvec3 n;
        double c;
        glm::dvec3 shading_normal;
    };
    const std::vector<LocalPlane> &planes() const { return planes_; }
    double zexag() const { return zexag_; }

private:
    bool hit_in_cell(uint64_t cell, double z_in, double z_out, double oz,
                     double dz, double t_in, Face wall, Hit &hit) const;

    const Model &model_;
    double zexag_;
    std::vector<LocalPlane> planes_;
    double z_max_local_ = 0; ///< highest interval top, local units
    glm::dvec3 scale_;       ///< map -> local per axis (exaggerated map)
};

} // namespace sbrt

#endif
