/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What a render draws besides the model's stacks: clip planes,
 *            translucent strata, borehole cylinders and fence curtains
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SCENE_HPP
#define SBRT_SCENE_HPP

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "model/model.hpp"

namespace sbrt {

/// \brief A clip plane in real map coordinates: everything on the side the
/// normal points to is removed (what is left is cut open along the plane).
struct ClipPlane {
    glm::dvec3 point;
    glm::dvec3 normal; ///< not zero; need not be unit length
};

/// Most clip planes one render takes (the GPU's view block holds them).
constexpr int MAX_CLIP_PLANES = 8;

/// \brief Translucent materials (Beer-Lambert): a ray that travels a length
/// L (exaggerated map units) through material m keeps exp(-extinction[m] L)
/// of the light behind it and adds the rest in colour[m]. An infinite
/// extinction is an opaque material; the vectors are empty when every
/// material is opaque.
struct Translucency {
    std::vector<double> extinction;  ///< per material index, per map unit
    std::vector<glm::dvec3> color;   ///< per material index, 0..1
    /// What a surface without thickness (a fence curtain) absorbs: as much
    /// as this length (map units) of the material.
    double length = 1;
    bool empty() const { return extinction.empty(); }
    bool opaque(uint32_t material) const
    {
        return extinction.empty() ||
               extinction[material] == std::numeric_limits<double>::infinity();
    }
};

/// Extinction per map unit of a material that absorbs the share `alpha`
/// (0..1) of the light over `length` map units (infinite: opaque).
inline double extinction_of(double alpha, double length)
{
    return alpha >= 1 ? std::numeric_limits<double>::infinity()
                      : -std::log1p(-alpha) / length;
}

/// \brief A vertical borehole: a cylinder about (x, y) through the whole
/// model, coloured by its own stack (the model's stack at the point, or the
/// logged intervals); `model_stack` is the model's stack there, for the
/// half-model side of a split cylinder.
struct Borehole {
    double x = 0, y = 0;  ///< map coordinates of the axis
    std::vector<Interval> stack;        ///< what the cylinder shows
    std::vector<Interval> model_stack;  ///< the model's stack at the point
};

/// \brief A vertical curtain below one segment of a fence line (map x, y),
/// from the model's bottom to its top.
struct FencePanel {
    glm::dvec2 a, b;
};

/// \brief Everything a Tracer draws. `draw_model` false leaves only the
/// boreholes and fence curtains (the model's stacks are not read).
struct Scene {
    std::vector<ClipPlane> planes;
    Translucency translucency;
    std::vector<Borehole> boreholes;
    double borehole_radius = 0;   ///< map units
    /// Split cylinders: the half on the side this horizontal direction
    /// points to shows the log (`stack`), the other half `model_stack`.
    std::optional<glm::dvec2> split;
    std::vector<FencePanel> fence;
    bool draw_model = true;
    /// Rays cross cells and blocks of cells that hold nothing at their
    /// height in one step (a min-max pyramid); false walks every cell
    /// (the same image, for benchmarks).
    bool skip_empty_space = true;
    /// Per material index, 1 where the material is hidden while tracing:
    /// its intervals are crossed as air, as if hide_materials had removed
    /// them, without a pass over the model (empty: none hidden); on a GPU
    /// a material that absorbs nothing. Not with boreholes or a fence,
    /// which read the stacks themselves.
    std::vector<uint8_t> hidden{};
};

} // namespace sbrt

#endif
