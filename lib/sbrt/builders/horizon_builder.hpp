/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Builds an SBRT with continuous heights from stacked horizons
 *            (top elevation of each unit, top to bottom), no voxels involved
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_HORIZON_BUILDER_HPP
#define SBRT_HORIZON_BUILDER_HPP

#include "model/model.hpp"

namespace sbrt {

/// \brief Stacks units between horizons, one grid row at a time (north first).
///
/// Unit i lies between its top horizon and the top of the next present unit
/// below it (or the bottom surface). A unit whose top lies below a lower
/// unit's top has zero thickness there; a NaN top means the unit is absent.
/// Elevations are map units; they are clamped into the frame.
class HorizonStackBuilder {
public:
    /// `units` are the materials of the units, top to bottom (ids != NULL).
    HorizonStackBuilder(const Frame &frame, std::vector<Material> units);

    /// `tops[i][col]` top of unit i, `bottom[col]` base (NaN: frame bottom).
    void add_row(const std::vector<const double *> &tops, const double *bottom);
    Model finish();

    /// Heights that fell outside the frame and were clamped into it.
    uint64_t clamped() const { return clamped_; }

private:
    double to_local(double z);
    void push(uint32_t material, double top);

    Frame frame_;
    std::vector<Material> materials_;
    std::vector<uint32_t> unit_material_;
    std::vector<uint32_t> offsets_{0};
    Intervals intervals_;
    std::vector<double> effective_top_;
    int row_ = 0;
    uint64_t clamped_ = 0;
};

} // namespace sbrt

#endif
