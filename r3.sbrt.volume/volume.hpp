/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   What the module is asked, the zones of an area map, and the
 *            report in plain, JSON or CSV form
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_VOLUME_HPP
#define R3_SBRT_VOLUME_HPP

#include <cstdio>
#include <string>
#include <vector>

#include "grass.hpp"
#include "measure/cell_zones.hpp"
#include "measure/class_set.hpp"
#include "measure/expected_thickness.hpp"
#include "measure/volumes.hpp"
#include "output_format.hpp"

/// \brief Options read.
struct VolumeRequest {
    std::string input;
    std::vector<std::string> classes; ///< empty: every class, one row each
    std::string probability;          ///< channels in % (a+b): expected volumes
    std::string areas, layer;         ///< areas empty: the region
    sbrt_grass::OutputFormat format = sbrt_grass::OutputFormat::plain;
    char separator = ','; ///< of csv
    std::string output; ///< empty or "-": standard output
    unsigned threads = 0;
    /// memory= in bytes: the model is read band by band within it
    /// (probability= reads it whole: its channels lie by columns)
    uint64_t memory = uint64_t(300) << 20;
};

/// \brief The zones of the cells counted, and the rows of the report:
/// the region's (one zone, one row), or a row per category of the area
/// map, which counts the cells in the region whose centre lies in an area
/// of that category (a cell may count for several).
struct Zones {
    sbrt::CellZones cells;
    std::vector<int> categories; ///< per row; empty for the region
    /// per zone of `cells`, the rows (indices into categories) its cells
    /// count for; empty: zone z is row z
    std::vector<std::vector<int>> counts_for;
};

/// The areas of vector map `name` (layer `layer`) as zones of the model's
/// cells within `region`; throws sbrt::Error for a map without areas.
Zones area_zones(const sbrt::Frame &frame, const std::string &name, const std::string &layer,
                 const sbrt::CellZones &region);

/// \brief What the report shows.
struct VolumeReport {
    std::string input;
    std::string units;                 ///< map units, plural ("meters")
    std::vector<sbrt::ClassSet> sets;  ///< a row each
    std::vector<int> categories;       ///< zones' categories, empty: region
    const std::vector<sbrt::Material> *materials = nullptr; ///< the model's table
    std::string probability;                    ///< probability=, or empty
    std::vector<sbrt::ExpectedVolume> expected; ///< its volume per zone
};

/// Writes `table` to `out` in `format` (plain, json or csv with `separator`).
void write_report(FILE *out, sbrt_grass::OutputFormat format, char separator, const VolumeReport &report,
                  const sbrt::VolumeTable &table);

/// Reads the SBRT, measures and writes the report (throws sbrt::Error).
void report_volumes(const VolumeRequest &request);

#endif
