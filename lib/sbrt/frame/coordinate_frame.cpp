/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The coordinate frame of a model as drawn
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frame/coordinate_frame.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "util/error.hpp"

namespace sbrt {

CoordinateFrame::CoordinateFrame(const Frame &grid, double zexag, double top_local)
    : grid_(grid), zexag_(zexag), top_local_(top_local)
{
    if (!(zexag > 0) || !std::isfinite(zexag))
        fail("vertical exaggeration ", zexag, ": it must be a positive number");
    scale_ = glm::dvec3(1.0 / grid.ew_res(), 1.0 / grid.ns_res(),
                        1.0 / (grid.tb_res() * zexag));
    // the exaggerated box must stay within double's range: a height times
    // zexag beyond it would turn every camera into infinities
    const double height = (grid.top - grid.bottom) * zexag;
    if (!std::isfinite(height) || !std::isfinite(glm::length(scale_)) ||
        !(height < 1e150))
        fail("vertical exaggeration ", zexag, ": too large for a model ",
             grid.top - grid.bottom, " map units high (its exaggerated height "
             "must stay below 1e150)");
}

CoordinateFrame CoordinateFrame::of(const Model &model, double zexag)
{
    return CoordinateFrame(model.frame(), zexag, highest_top_local(model));
}

glm::dvec3 CoordinateFrame::exaggerated_from_map(glm::dvec3 map) const
{
    const double b = grid_.bottom;
    return {map.x, map.y, b + (map.z - b) * zexag_};
}

glm::dvec3 CoordinateFrame::map_from_exaggerated(glm::dvec3 exaggerated) const
{
    const double b = grid_.bottom;
    return {exaggerated.x, exaggerated.y, b + (exaggerated.z - b) / zexag_};
}

glm::dvec3 CoordinateFrame::local_from_exaggerated(glm::dvec3 exaggerated) const
{
    return (exaggerated - glm::dvec3(grid_.west, grid_.south, grid_.bottom)) * scale_;
}

glm::dvec3 CoordinateFrame::map_from_local(glm::dvec3 local) const
{
    return {grid_.west + local.x * grid_.ew_res(), grid_.south + local.y * grid_.ns_res(),
            grid_.bottom + local.z * grid_.tb_res()};
}

double CoordinateFrame::top_elevation() const
{
    return grid_.bottom + top_local_ * grid_.tb_res();
}

glm::dvec3 CoordinateFrame::centre() const
{
    return exaggerated_from_map({(grid_.east + grid_.west) / 2, (grid_.north + grid_.south) / 2,
                                 (grid_.bottom + top_elevation()) / 2});
}

glm::dvec3 CoordinateFrame::corner(int k) const
{
    return exaggerated_from_map({k & 1 ? grid_.east : grid_.west, k & 2 ? grid_.north : grid_.south,
                                 k & 4 ? top_elevation() : grid_.bottom});
}

double CoordinateFrame::radius() const
{
    return glm::length(corner(7) - corner(0)) / 2;
}

double highest_top_local(const Model &model)
{
    if (const StackPages *pages = model.pages())
        return pages->highest_top_local();
    double top = 0;
    const uint64_t cells = model.frame().cells();
    for (uint64_t c = 0; c < cells; ++c)
        top = std::max(top, model.stack_top(c));
    return top;
}

} // namespace sbrt
