/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Cameras in map coordinates (+z up, right-handed): perspective,
 *            orthographic and top views; one ray per pixel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CAMERA_HPP
#define SBRT_CAMERA_HPP

#include <glm/vec3.hpp>

#include "model.hpp"

namespace sbrt {

/// A ray in map coordinates with vertical exaggeration applied.
struct Ray {
    glm::dvec3 origin;
    glm::dvec3 direction; ///< unit length
};

/// Right and up vectors of a view along unit `forward`: +z is up unless the
/// view is vertical, then north (+y) is up.
void view_basis(glm::dvec3 forward, glm::dvec3 &right, glm::dvec3 &up);

/// \brief Pixel (row, col) of a rows x cols image -> ray. Pixel (r, c)
/// looks through the image-plane point at normalised device coordinates
/// ((c + 0.5) / cols * 2 - 1, 1 - (r + 0.5) / rows * 2).
class Camera {
public:
    enum class Kind { perspective, orthographic, top };

    /// `position` and `target` in (exaggerated) map coordinates.
    static Camera perspective(glm::dvec3 position, glm::dvec3 target,
                              double fov_degrees, int rows, int cols);
    static Camera orthographic(glm::dvec3 position, glm::dvec3 target,
                               double height, int rows, int cols);
    /// Straight down through the centre of each cell of a 2D grid.
    static Camera top(double north, double south, double east, double west,
                      double above, int rows, int cols);

    Ray ray(int row, int col) const;
    int rows() const { return rows_; }
    int cols() const { return cols_; }

private:
    Kind kind_ = Kind::perspective;
    int rows_ = 1, cols_ = 1;
    glm::dvec3 position_{0}, forward_{0, 0, -1}, right_{1, 0, 0}, up_{0, 1, 0};
    double half_height_ = 1, half_width_ = 1; ///< tan(fov/2) or map units
    double north_ = 0, west_ = 0, ns_res_ = 1, ew_res_ = 1, above_ = 0;
};

} // namespace sbrt

#endif
