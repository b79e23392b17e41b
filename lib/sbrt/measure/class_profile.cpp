/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The classes a vertical section along a line cuts
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "measure/class_profile.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// A column's intervals bottom up as (top, class id) in local heights:
/// each starts at the one before's top (0 for the first).
struct Column {
    std::vector<double> tops;
    std::vector<int32_t> ids;

    /// Class at local height `z`: the first interval whose top lies above.
    int32_t at(double z) const
    {
        if (!(z >= 0))
            return NULL_CLASS;
        const size_t i = size_t(std::upper_bound(tops.begin(), tops.end(), z) - tops.begin());
        return i < ids.size() ? ids[i] : NULL_CLASS;
    }
};

/// The column of the cell under map point `p`; empty off the model.
Column column_under(const Model &model, glm::dvec2 p)
{
    Column column;
    const auto cell = cell_of_point(model.frame(), p.x, p.y);
    if (!cell)
        return column;
    model.visit_stack(model.cell_index(cell->row, cell->col), [&](const auto *first,
                                                                  const auto *last) {
        column.tops.reserve(size_t(last - first));
        column.ids.reserve(size_t(last - first));
        for (const auto *r = first; r != last; ++r) {
            const uint32_t m = r->material;
            column.tops.push_back(double(r->top));
            column.ids.push_back(m == EMPTY ? NULL_CLASS : model.materials()[m].id);
        }
    });
    return column;
}

} // namespace

ClassProfile class_profile(const Model &model, const ProfileLine &line, int cols, int rows,
                           ProfileExtent extent, uint64_t max_cells)
{
    if (cols < 1 || rows < 1)
        fail("a profile needs at least one row and one column (", rows, " x ", cols, ")");
    if (uint64_t(rows) * uint64_t(cols) > max_cells)
        fail("a profile of ", rows, " x ", cols, " cells is larger than the ", max_cells,
             " allowed: ask for a coarser resolution");
    if (!std::isfinite(extent.bottom) || !std::isfinite(extent.top) ||
        !(extent.top > extent.bottom))
        fail("a profile's elevations must rise from bottom to top (", extent.bottom, " to ",
             extent.top, ")");
    ClassProfile profile;
    profile.rows = rows;
    profile.cols = cols;
    profile.length = line.length();
    profile.extent = extent;
    profile.classes.assign(size_t(rows) * size_t(cols), NULL_CLASS);
    const Frame &frame = model.frame();
    for (int c = 0; c < cols; ++c) {
        const Column column = column_under(model, line.column_point(c, cols));
        if (column.ids.empty())
            continue;
        for (int r = 0; r < rows; ++r)
            profile.classes[size_t(r) * size_t(cols) + size_t(c)] =
                column.at(frame.local_z(profile.elevation(r)));
    }
    return profile;
}

std::optional<ProfileExtent> solid_extent(const Model &model, const ProfileLine &line,
                                          int samples)
{
    const Frame &frame = model.frame();
    double lowest = HUGE_VAL, highest = -HUGE_VAL;
    for (int s = 0; s < samples; ++s) {
        const Column column = column_under(model, line.column_point(s, samples));
        for (size_t i = 0; i < column.ids.size(); ++i) {
            if (column.ids[i] == NULL_CLASS)
                continue;
            lowest = std::min(lowest, i ? column.tops[i - 1] : 0.0);
            highest = std::max(highest, column.tops[i]);
        }
    }
    if (!(highest > lowest))
        return std::nullopt;
    return ProfileExtent{frame.bottom + lowest * frame.tb_res(),
                         frame.bottom + highest * frame.tb_res()};
}

} // namespace sbrt
