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

/// \brief The sums of measure_volumes made band by band: a model read in
/// bands of whole rows (any split) gives the table of the whole model,
/// figure for figure (each row block's rows are added in row order).
class VolumeSums {
public:
    /// For a model of `frame` with `materials` materials; `zones` of its
    /// cells (the whole frame's).
    VolumeSums(const Frame &frame, size_t materials, const std::vector<ClassSet> &sets,
               const CellZones &zones, unsigned threads = 0);
    /// Adds `band`: the whole model's rows from `first_row` on (full
    /// width); bands in any order, each row once.
    void add_band(const Model &band, int first_row);
    VolumeTable table() const;

private:
    /// Sums in local units (exact integers for voxel models), per zone
    /// and set, of one row block.
    struct Sums {
        std::vector<double> thickness;
        std::vector<uint64_t> cells;
    };
    template <typename Record>
    void add_rows(const Model &band, const Record *records, int band_first, int first,
                  int last, Sums &sums) const;

    Frame frame_;
    std::vector<ClassSet> sets_;
    const CellZones &zones_;
    unsigned threads_;
    std::vector<std::vector<uint32_t>> sets_of_;
    std::vector<Sums> block_sums_;
};

/// One set per class of the model, in the order of the class ids.
std::vector<ClassSet> every_class(const Model &model);
std::vector<ClassSet> every_class(const std::vector<Material> &table);

} // namespace sbrt

#endif
