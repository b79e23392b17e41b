/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Cameras in map coordinates (+z up, right-handed): perspective,
 *            orthographic and top views; one ray per pixel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CAMERA_HPP
#define SBRT_CAMERA_HPP

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "model/model.hpp"

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
/// (x, y) = ((c + 0.5) / cols * 2 - 1, 1 - (r + 0.5) / rows * 2).
/// Every kind is linear in (x, y): a perspective ray starts at `origin`
/// along normalize(forward + x du + y dv); a parallel ray starts at
/// origin + x du + y dv along `forward`.
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

    /// Rows [first, first + count) of this image as an image of their own,
    /// with the same rays: a large image traced band by band.
    Camera rows_window(int first, int count) const;
    /// The rectangle of rows [first_row, first_row + rows) and columns
    /// [first_col, first_col + cols) as an image of its own (a tile): ray()
    /// gives the very rays of the whole image's pixels, bit for bit.
    Camera window(int first_row, int rows, int first_col, int cols) const;
    bool is_window() const { return rows_ != root_rows_ || cols_ != root_cols_; }

    Ray ray(int row, int col) const;
    /// Normalised device coordinates of the centre of pixel (row, col) of
    /// this image (a window's own), as linear_rays takes them.
    glm::dvec2 pixel_ndc(int row, int col) const
    {
        return {(col + 0.5) / cols_ * 2 - 1, 1 - (row + 0.5) / rows_ * 2};
    }
    /// The rays of this image (a window's own) as linear forms in (x, y):
    /// a perspective ray starts at `origin` along normalize(forward + x du
    /// + y dv); a parallel ray starts at origin + x du + y dv along
    /// `forward`.
    void linear_rays(glm::dvec3 &origin, glm::dvec3 &forward, glm::dvec3 &du,
                     glm::dvec3 &dv) const;
    /// Normalised device coordinates (x, y) of the ray through point p;
    /// false where p is not in front of a perspective camera.
    bool project(glm::dvec3 p, double &x, double &y) const;
    /// Where p falls in this image as three linear forms of (p - origin(),
    /// 1): with (c, r, w) their values, the pixel position is (c / w, r /
    /// w), pixel centres whole and rows from the top (project's x, y as (x
    /// + 1) / 2 cols - 0.5 and (1 - y) / 2 rows - 0.5); w > 0 where p lies
    /// in front of a perspective camera, 1 for a parallel one.
    std::array<glm::dvec4, 3> pixel_rows() const;
    int rows() const { return rows_; }
    int cols() const { return cols_; }
    bool parallel() const { return kind_ != Kind::perspective; }
    glm::dvec3 origin() const { return origin_; }
    glm::dvec3 forward() const { return forward_; }
    /// Image-plane steps per unit of normalised device x and y (of the
    /// whole image, where this is a window).
    glm::dvec3 du() const { return du_; }
    glm::dvec3 dv() const { return dv_; }

private:
    Kind kind_ = Kind::perspective;
    int rows_ = 1, cols_ = 1;
    glm::dvec3 origin_{0}, forward_{0, 0, -1}, du_{1, 0, 0}, dv_{0, 1, 0};
    /// a window: the whole image's size and the window's first row and
    /// column in it
    int root_rows_ = 1, root_cols_ = 1, row0_ = 0, col0_ = 0;
    /// a window's y = offset + scale * its own y, and x alike (linear_rays,
    /// project)
    double window_offset_ = 0, window_scale_ = 1, x_offset_ = 0, x_scale_ = 1;
};

} // namespace sbrt

#endif
