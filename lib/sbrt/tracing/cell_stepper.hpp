/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The tracer's walk over the grid: a 2D DDA (Amanatides and
 *            Woo 1987) as a stepper object, one cell's stretch of the ray
 *            at a time
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CELL_STEPPER_HPP
#define SBRT_CELL_STEPPER_HPP

#include <algorithm>
#include <cmath>

#include "tracing/tracer.hpp"

namespace sbrt {

/// \brief The cells of a grid (`cols` x `rows`, x and y in cells from the
/// west and south edges, as the tracer's local frame) that the ray o + t d
/// crosses from t_near to t_far, in order, as pbrt-v4's
/// DDAMajorantIterator walks its grid. The constructor finds the first
/// cell and the parameters at which the ray reaches the next wall along x
/// and along y; each stretch of the ray is cell (x(), y()) over [t_in(),
/// t_out()], entered through face(). next() steps into the neighbour the
/// ray enters at t_out(); jump_to() goes to a cell further on (beyond a
/// block of cells the tracer skips). A direction component of 0 (never
/// -0: the tracer normalises it) has an inverse of +inf and never reaches
/// a wall. The walk ends (done()) at t_far or off the grid.
class CellStepper {
public:
    /// `inv_dx`, `inv_dy`: 1 / dx and 1 / dy; `face`: the face the ray
    /// enters its first cell through.
    CellStepper(double ox, double oy, double dx, double dy, double inv_dx, double inv_dy,
                double t_near, double t_far, Face face, int cols, int rows)
        : ox_(ox), oy_(oy), inv_dx_(inv_dx), inv_dy_(inv_dy), t_in_(t_near),
          t_far_(t_far), cols_(cols), rows_(rows), step_x_(dx > 0 ? 1 : -1),
          step_y_(dy > 0 ? 1 : -1), wall_x_(dx > 0), wall_y_(dy > 0),
          moves_x_(dx != 0), moves_y_(dy != 0),
          face_x_(dx > 0 ? Face::west : Face::east),
          face_y_(dy > 0 ? Face::south : Face::north), face_(face)
    {
        // the entry point's cell, clamped: the entry lies on the grid's
        // edge up to rounding
        x_ = std::clamp(int(std::floor(ox + t_near * dx)), 0, cols - 1);
        y_ = std::clamp(int(std::floor(oy + t_near * dy)), 0, rows - 1);
        set_walls();
    }

    bool done() const { return done_; }
    int x() const { return x_; }
    int y() const { return y_; }
    /// The stretch of the ray in the current cell.
    double t_in() const { return t_in_; }
    double t_out() const { return std::max(t_in_, std::min(std::min(t_max_x_, t_max_y_), t_far_)); }
    double t_far() const { return t_far_; }
    /// The face the current cell was entered through.
    Face face() const { return face_; }

    /// Into the cell beyond t_out() (a tie steps along y).
    void next()
    {
        if (t_out() >= t_far_) {
            done_ = true;
            return;
        }
        // each wall's t from its own position, not summed step by step:
        // a cell is entered at the same t however the walk came to it
        // (stepped, or jumped beyond a block of cells the tracer skips)
        if (t_max_x_ < t_max_y_) {
            x_ += step_x_;
            t_in_ = t_max_x_;
            t_max_x_ = ((x_ + wall_x_) - ox_) * inv_dx_;
            face_ = face_x_;
        }
        else {
            y_ += step_y_;
            t_in_ = t_max_y_;
            t_max_y_ = ((y_ + wall_y_) - oy_) * inv_dy_;
            face_ = face_y_;
        }
        done_ = !on_grid();
    }

    /// Into cell (x, y), entered at t through `face` (t >= t_in()).
    void jump_to(int x, int y, double t, Face face)
    {
        if (t >= t_far_) {
            done_ = true;
            return;
        }
        x_ = x;
        y_ = y;
        t_in_ = t;
        face_ = face;
        done_ = !on_grid();
        if (!done_)
            set_walls();
    }

private:
    bool on_grid() const { return x_ >= 0 && x_ < cols_ && y_ >= 0 && y_ < rows_; }

    /// t where the ray reaches the current cell's far walls along x and y.
    void set_walls()
    {
        t_max_x_ = moves_x_ ? ((x_ + wall_x_) - ox_) * inv_dx_ : INFINITY;
        t_max_y_ = moves_y_ ? ((y_ + wall_y_) - oy_) * inv_dy_ : INFINITY;
    }

    double ox_, oy_, inv_dx_, inv_dy_;
    double t_in_, t_far_, t_max_x_ = INFINITY, t_max_y_ = INFINITY;
    int cols_, rows_, x_ = 0, y_ = 0, step_x_, step_y_, wall_x_, wall_y_;
    bool moves_x_, moves_y_;
    Face face_x_, face_y_, face_;
    bool done_ = false;
};

} // namespace sbrt

#endif
