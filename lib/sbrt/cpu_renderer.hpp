/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Renders an image with the exact tracer on all cores: colour
 *            (Lambert shading), material, elevation and depth per pixel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CPU_RENDERER_HPP
#define SBRT_CPU_RENDERER_HPP

#include <array>
#include <vector>

#include "camera.hpp"
#include "model.hpp"

namespace sbrt {

/// \brief Lighting I = ia + kd (L.N) id with kd id = 1 - ambient.
struct Shading {
    glm::dvec3 light{0, 0, 1}; ///< towards the light, unit length
    double ambient = 0.35;
    std::array<uint8_t, 3> background{255, 255, 255};

    /// Direction from azimuth (degrees clockwise from north) and elevation.
    static glm::dvec3 light_from(double azimuth, double elevation);
};

/// \brief Per-pixel outputs, row-major, row 0 at the top of the image.
struct Image {
    int rows = 0, cols = 0;
    std::vector<uint8_t> rgb;       ///< 3 per pixel
    std::vector<int32_t> material;  ///< class id, NULL_CLASS where missed
    std::vector<double> elevation;  ///< z of the hit, NaN where missed
    std::vector<double> depth;      ///< distance from the ray origin, NaN
};

/// Colour of a material: its stored colour, else a fixed palette entry.
std::array<uint8_t, 3> material_color(const Model &model, uint32_t material);

/// Renders with `threads` threads (0: all cores).
Image render_cpu(const Model &model, const Camera &camera, double zexag,
                 const Shading &shading, unsigned threads = 0);

} // namespace sbrt

#endif
