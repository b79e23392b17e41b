/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Drape of a colour image on the terrain surface
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "shading/drape.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

bool Texture::sample(double x, double y, glm::dvec3 &rgb_out) const
{
    if (rows <= 0 || cols <= 0 || !(x >= west && x <= east && y >= south && y <= north))
        return false;
    // position among the cell centres
    const double u = (x - west) / (east - west) * cols - 0.5;
    const double v = (north - y) / (north - south) * rows - 0.5;
    const int c0 = int(std::floor(u)), r0 = int(std::floor(v));
    const double fu = u - c0, fv = v - r0;
    glm::dvec3 sum(0);
    double weight = 0;
    for (int dr = 0; dr < 2; ++dr)
        for (int dc = 0; dc < 2; ++dc) {
            const int r = std::clamp(r0 + dr, 0, rows - 1);
            const int c = std::clamp(c0 + dc, 0, cols - 1);
            const size_t i = size_t(r) * size_t(cols) + size_t(c);
            if (!valid[i])
                continue;
            const double w = (dc ? fu : 1 - fu) * (dr ? fv : 1 - fv);
            sum += w * glm::dvec3(rgb[i][0], rgb[i][1], rgb[i][2]);
            weight += w;
        }
    if (!(weight > 0))
        return false;
    rgb_out = sum / weight;
    return true;
}

Drape::Drape(const Model &model, Texture texture, double blend)
    : frame_(model.frame()), surface_(model.frame().cells(), -1.0f),
      texture_(std::move(texture)), blend_(blend)
{
    if (!(blend >= 0 && blend <= 1))
        fail("drape: the blend ", blend, " must lie in 0..1");
    if (texture_.rgb.size() != size_t(texture_.rows) * size_t(texture_.cols) ||
        texture_.valid.size() != texture_.rgb.size())
        fail("drape: the texture's pixels do not match its ", texture_.rows,
             " x ", texture_.cols, " grid");
    for (uint64_t c = 0; c < frame_.cells(); ++c)
        if (model.stack_size(c)) // no trailing EMPTY: the last one is solid
            surface_[c] = model.intervals()[model.stack_end(c) - 1].top;
}

float Drape::surface(int row, int col) const
{
    if (row < 0 || row >= frame_.rows || col < 0 || col >= frame_.cols)
        return -1;
    return surface_[uint64_t(row) * uint64_t(frame_.cols) + uint64_t(col)];
}

bool Drape::on_surface(const Hit &hit) const
{
    const double z = frame_.local_z(hit.point.z);
    const double u = (hit.point.x - frame_.west) / frame_.ew_res();
    const double v = (frame_.north - hit.point.y) / frame_.ns_res(); // rows
    constexpr double EPS = SURFACE_EPS;
    if (hit.face == Face::top) {
        const float top = surface(std::clamp(int(std::floor(v)), 0, frame_.rows - 1),
                                  std::clamp(int(std::floor(u)), 0, frame_.cols - 1));
        return top >= 0 && std::fabs(z - top) <= EPS;
    }
    // a wall of the terrain's staircase: between the cell's surface and
    // the lower surface of the neighbour it faces (not the model's sides)
    int row = 0, col = 0, d_row = 0, d_col = 0;
    switch (hit.face) {
    case Face::west: col = int(std::lround(u)); row = int(std::floor(v)); d_col = -1; break;
    case Face::east: col = int(std::lround(u)) - 1; row = int(std::floor(v)); d_col = 1; break;
    case Face::north: row = int(std::lround(v)); col = int(std::floor(u)); d_row = -1; break;
    case Face::south: row = int(std::lround(v)) - 1; col = int(std::floor(u)); d_row = 1; break;
    default: return false;
    }
    const float own = surface(row, col), facing = surface(row + d_row, col + d_col);
    return own >= 0 && facing >= 0 && z <= own + EPS && z >= facing - EPS;
}

glm::dvec3 Drape::color(const Hit &hit, glm::dvec3 class_color) const
{
    glm::dvec3 rgb;
    if (!on_surface(hit) || !texture_.sample(hit.point.x, hit.point.y, rgb))
        return class_color;
    return class_color + blend_ * (rgb - class_color);
}

} // namespace sbrt
