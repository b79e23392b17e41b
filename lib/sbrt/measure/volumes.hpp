/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Volumes of class sets per zone: the sum over the counted
 *            model cells of the set's thickness times the cell's area,
 *            and the number of cells the set is in
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VOLUMES_HPP
#define SBRT_VOLUMES_HPP

#include <cstdint>
#include <vector>

#include "measure/cell_zones.hpp"
#include "measure/class_set.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief A class set in one zone.
struct Volume {
    double volume = 0;       ///< cubic map units
    double thickness = 0;    ///< sum over the cells of the set's thickness, map units
    uint64_t cells = 0;      ///< counted cells where the set has a thickness
};

/// \brief Volumes of several sets in several zones.
class VolumeTable {
public:
    VolumeTable(size_t sets, int zones) : sets_(sets), zones_(zones), volumes_(sets * size_t(zones)) {}
    size_t sets() const { return sets_; }
    int zones() const { return zones_; }
    const Volume &at(int zone, size_t set) const { return volumes_[size_t(zone) * sets_ + set]; }
    Volume &at(int zone, size_t set) { return volumes_[size_t(zone) * sets_ + set]; }

private:
    size_t sets_;
    int zones_;
    std::vector<Volume> volumes_;
};

/// The volume of each of `sets` in each zone of `zones`, one pass over
/// the intervals of the counted cells on `threads` threads (0: all cores).
/// Sums are made in a fixed order of row blocks, so that the figures do
/// not depend on the threads. A material may belong to several sets.
VolumeTable measure_volumes(const Model &model, const std::vector<ClassSet> &sets,
                            const CellZones &zones, unsigned threads = 0);

/// One set per class of the model, in the order of the class ids.
std::vector<ClassSet> every_class(const Model &model);

} // namespace sbrt

#endif
