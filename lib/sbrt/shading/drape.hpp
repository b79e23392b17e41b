/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Drape of a 2D colour image (an orthophoto) on the terrain
 *            surface of a model: the top of each cell's topmost non-empty
 *            interval, resampled bilinearly
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_DRAPE_HPP
#define SBRT_DRAPE_HPP

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "tracing/tracer.hpp"

namespace sbrt {

/// \brief An RGB image on a georeferenced grid (row 0 north); cells
/// without a value are skipped by the resampling.
struct Texture {
    double north = 1, south = 0, east = 1, west = 0;
    int rows = 0, cols = 0;
    std::vector<std::array<uint8_t, 3>> rgb; ///< rows * cols
    std::vector<uint8_t> valid;               ///< rows * cols, 0 or 1

    /// Bilinear colour (0..255) at map (x, y) from the four nearest cell
    /// centres that hold a value; false where none does or (x, y) lies
    /// outside the grid.
    bool sample(double x, double y, glm::dvec3 &rgb_out) const;
};

/// \brief What is draped where: the texture on the surface of `model`, its
/// cells' tops and the walls of the staircase between them.
class Drape {
public:
    /// `model` is the model as read, before strata are hidden: the drape
    /// stays on the terrain, never on a subcrop.
    Drape(const Model &model, Texture texture, double blend);

    /// The colour of `hit` with the texture mixed in where it lies on the
    /// terrain surface.
    glm::dvec3 color(const Hit &hit, glm::dvec3 class_color) const;

    /// Whether the hit lies on the terrain: on the top of a cell's topmost
    /// interval, or on a wall between a cell's top and the lower top of
    /// the neighbour it faces.
    bool on_surface(const Hit &hit) const;

    /// What the GPU's drape reads (gpu/gpu_layout.hpp, make_gpu_drape).
    const Frame &frame() const { return frame_; }
    /// Per cell (row from the north, column), the local z of its surface;
    /// < 0 where the cell is empty.
    const std::vector<float> &surface_tops() const { return surface_; }
    const Texture &texture() const { return texture_; }
    double blend() const { return blend_; }
    /// The tolerance (local z) of on_surface: the GPU's points are floats.
    static constexpr double SURFACE_EPS = 1e-3;

private:
    float surface(int row, int col) const; ///< local z; < 0: none or outside

    Frame frame_;
    std::vector<float> surface_; ///< per cell, local z; < 0 where empty
    Texture texture_;
    double blend_;
};

} // namespace sbrt

#endif
