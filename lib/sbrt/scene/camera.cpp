/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Camera rays
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/camera.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.hpp"

namespace sbrt {

void view_basis(glm::dvec3 forward, glm::dvec3 &right, glm::dvec3 &up)
{
    glm::dvec3 world_up(0, 0, 1);
    if (std::fabs(forward.z) > 1 - 1e-12)
        world_up = glm::dvec3(0, 1, 0);
    right = glm::normalize(glm::cross(forward, world_up));
    up = glm::cross(right, forward);
}

namespace {

void check_image(int rows, int cols)
{
    if (rows < 1 || cols < 1)
        fail("Camera: image of ", rows, " x ", cols, " pixels");
}

glm::dvec3 view_direction(glm::dvec3 position, glm::dvec3 target)
{
    const glm::dvec3 d = target - position;
    const double length = glm::length(d);
    if (!(length > 0) || !std::isfinite(length))
        fail("Camera: position and target must differ and be finite");
    return d / length;
}

} // namespace

Camera Camera::perspective(glm::dvec3 position, glm::dvec3 target,
                           double fov_degrees, int rows, int cols)
{
    check_image(rows, cols);
    if (!(fov_degrees > 0 && fov_degrees < 180))
        fail("Camera: field of view ", fov_degrees,
             " degrees is not in (0, 180)");
    Camera c;
    c.kind_ = Kind::perspective;
    c.rows_ = rows;
    c.cols_ = cols;
    c.root_rows_ = rows;
    c.root_cols_ = cols;
    c.origin_ = position;
    c.forward_ = view_direction(position, target);
    glm::dvec3 right, up;
    view_basis(c.forward_, right, up);
    const double half_height = std::tan(fov_degrees * M_PI / 360.0);
    c.du_ = right * (half_height * cols / rows);
    c.dv_ = up * half_height;
    return c;
}

Camera Camera::orthographic(glm::dvec3 position, glm::dvec3 target,
                            double height, int rows, int cols)
{
    check_image(rows, cols);
    if (!(height > 0) || !std::isfinite(height))
        fail("Camera: orthographic height ", height, " must be positive");
    Camera c;
    c.kind_ = Kind::orthographic;
    c.rows_ = rows;
    c.cols_ = cols;
    c.root_rows_ = rows;
    c.root_cols_ = cols;
    c.forward_ = view_direction(position, target);
    glm::dvec3 right, up;
    view_basis(c.forward_, right, up);
    // centred on the target, rays start where the camera stands
    c.origin_ = target - c.forward_ * glm::dot(target - position, c.forward_);
    c.du_ = right * (height / 2 * cols / rows);
    c.dv_ = up * (height / 2);
    return c;
}

Camera Camera::top(double north, double south, double east, double west,
                   double above, int rows, int cols)
{
    check_image(rows, cols);
    Camera c;
    c.kind_ = Kind::top;
    c.rows_ = rows;
    c.cols_ = cols;
    c.root_rows_ = rows;
    c.root_cols_ = cols;
    c.forward_ = glm::dvec3(0, 0, -1);
    c.origin_ = glm::dvec3((east + west) / 2, (north + south) / 2, above);
    c.du_ = glm::dvec3((east - west) / 2, 0, 0);
    c.dv_ = glm::dvec3(0, (north - south) / 2, 0);
    return c;
}

Camera Camera::rows_window(int first, int count) const
{
    return window(first, count, 0, cols_);
}

Camera Camera::window(int first_row, int rows, int first_col, int cols) const
{
    if (first_row < 0 || rows < 1 || first_row + rows > rows_ || first_col < 0 ||
        cols < 1 || first_col + cols > cols_)
        fail("Camera: rows ", first_row, " to ", first_row + rows, " and columns ",
             first_col, " to ", first_col + cols, " are not within the ", rows_, " x ",
             cols_, " image");
    Camera c = *this;
    c.rows_ = rows;
    c.cols_ = cols;
    c.row0_ = row0_ + first_row;
    c.col0_ = col0_ + first_col;
    // y of the whole image's row row0 + r = offset + scale * y of row r in
    // the window, from y = 1 - (row + 0.5) / rows * 2; x alike
    const double R = root_rows_, C = root_cols_;
    c.window_scale_ = rows / R;
    c.window_offset_ = 1 - (2.0 * c.row0_ + rows) / R;
    c.x_scale_ = cols / C;
    c.x_offset_ = (2.0 * c.col0_ + cols) / C - 1;
    return c;
}

Ray Camera::ray(int row, int col) const
{
    // from the whole image's pixel indices: a tile's rays are its own
    const double x = (col0_ + col + 0.5) / root_cols_ * 2 - 1;
    const double y = 1 - (row0_ + row + 0.5) / root_rows_ * 2;
    if (parallel())
        return {origin_ + du_ * x + dv_ * y, forward_};
    return {origin_, glm::normalize(forward_ + du_ * x + dv_ * y)};
}

void Camera::linear_rays(glm::dvec3 &origin, glm::dvec3 &forward, glm::dvec3 &du,
                         glm::dvec3 &dv) const
{
    origin = origin_;
    forward = forward_;
    if (parallel())
        origin += window_offset_ * dv_ + x_offset_ * du_;
    else
        forward += window_offset_ * dv_ + x_offset_ * du_;
    du = x_scale_ * du_;
    dv = window_scale_ * dv_;
}

bool Camera::project(glm::dvec3 p, double &x, double &y) const
{
    // forward is unit length; du and dv are orthogonal to it and each other
    const glm::dvec3 v = p - origin_;
    double scale = 1;
    if (kind_ == Kind::perspective) {
        scale = glm::dot(v, forward_);
        if (!(scale > 0))
            return false;
    }
    x = (glm::dot(v, du_) / (scale * glm::dot(du_, du_)) - x_offset_) / x_scale_;
    y = (glm::dot(v, dv_) / (scale * glm::dot(dv_, dv_)) - window_offset_) / window_scale_;
    return std::isfinite(x) && std::isfinite(y);
}

std::array<glm::dvec4, 3> Camera::pixel_rows() const
{
    // project's x = (dot(v, du) / (s |du|^2) - x_offset) / x_scale with
    // v = p - origin, s = dot(v, forward) (1 parallel); then the pixel's
    // column (x + 1) / 2 cols - 0.5, and its row alike from y, downwards
    const auto form = [](glm::dvec3 a) { return glm::dvec4(a, 0); };
    const glm::dvec4 w = kind_ == Kind::perspective ? form(forward_) : glm::dvec4(0, 0, 0, 1);
    const glm::dvec4 x = form(du_ / glm::dot(du_, du_)), y = form(dv_ / glm::dot(dv_, dv_));
    const double cx = cols_ / (2 * x_scale_), cy = rows_ / (2 * window_scale_);
    return {x * cx + w * ((1 - x_offset_ / x_scale_) * cols_ / 2 - 0.5),
            y * -cy + w * ((1 + window_offset_ / window_scale_) * rows_ / 2 - 0.5), w};
}

} // namespace sbrt
