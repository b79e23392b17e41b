/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The coordinate frame of a model as drawn: vertical
 *            exaggeration, map <-> local coordinates, the box, its centre,
 *            radius and corners. A small value that cameras, paths,
 *            framing, pruning, the drape and annotations take; the tracer
 *            holds one and only traces
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COORDINATE_FRAME_HPP
#define SBRT_COORDINATE_FRAME_HPP

#include <glm/vec3.hpp>

#include "model/model.hpp"

namespace sbrt {

/// \brief Three spaces: "map", real map coordinates (x, y, elevation);
/// "exaggerated", exaggerated map coordinates (elevations stretched by
/// `zexag` about the model's bottom; what cameras live in); and "local", the
/// local frame (x, y in cells from the west and south edges, z in tb_res
/// steps from the bottom; what the tracers and the GPU walk), in which
/// coordinates in the millions never reach a float.
class CoordinateFrame {
public:
    /// The frame of `grid` drawn with `zexag`, its box up to `top_local`
    /// (local units: the highest top drawn). Throws sbrt::Error unless
    /// zexag is positive and finite.
    CoordinateFrame(const Frame &grid, double zexag, double top_local);
    /// The frame of `model`, its box up to the model's highest top.
    static CoordinateFrame of(const Model &model, double zexag);

    /// Transforms named `<to>_from_<from>` (pbrt-v4's renderFromCamera
    /// style), since all three spaces are glm::dvec3 and the type cannot
    /// tell them apart. Map -> exaggerated map, and back.
    glm::dvec3 exaggerated_from_map(glm::dvec3 map) const;
    glm::dvec3 map_from_exaggerated(glm::dvec3 exaggerated) const;
    /// Exaggerated map -> local, and local -> real map (not exaggerated:
    /// the two are not inverses).
    glm::dvec3 local_from_exaggerated(glm::dvec3 exaggerated) const;
    glm::dvec3 map_from_local(glm::dvec3 local) const;
    /// A direction in exaggerated map space, in the local frame.
    glm::dvec3 local_direction_from_exaggerated(glm::dvec3 direction) const
    {
        return direction * scale_;
    }
    /// Map -> local scale per axis (exaggerated map).
    glm::dvec3 scale() const { return scale_; }
    /// Size of a voxel in exaggerated map units (ew, ns, tb * zexag).
    glm::dvec3 voxel_size() const { return 1.0 / scale_; }

    /// Centre and half-diagonal of the box (exaggerated).
    glm::dvec3 centre() const;
    double radius() const;
    /// Corner k (0..7, bit 0 east, bit 1 north, bit 2 top) of the box,
    /// exaggerated map coordinates.
    glm::dvec3 corner(int k) const;
    /// Top of the box: the highest top drawn, map units and local units.
    double top_elevation() const;
    double top_local() const { return top_local_; }

    double zexag() const { return zexag_; }
    const Frame &grid() const { return grid_; }

private:
    Frame grid_;
    double zexag_;
    double top_local_;
    glm::dvec3 scale_;
};

/// Top of the highest interval of `model`, local units (0 where empty).
double highest_top_local(const Model &model);

} // namespace sbrt

#endif
