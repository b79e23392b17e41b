/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   Reads the SBRT, counts the model cells of the region (or of
 *            each area), measures the volumes and writes the report
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cstring>

#include "model/class_names.hpp"
#include "report_file.hpp"
#include "sbrt_bands.hpp"
#include "sbrt_store.hpp"
#include "module_errors.hpp"
#include "volume.hpp"

namespace {

/// The sums of the zones of cells folded into the report's rows (a zone
/// of cells may count for several rows).
sbrt::VolumeTable by_row(const Zones &zones, const sbrt::VolumeTable &table)
{
    if (zones.counts_for.empty())
        return table;
    sbrt::VolumeTable rows(table.sets(), int(zones.categories.size()));
    for (int z = 0; z < table.zones(); ++z)
        for (int row : zones.counts_for[size_t(z)])
            for (size_t s = 0; s < table.sets(); ++s) {
                const sbrt::Volume &v = table.at(z, s);
                sbrt::Volume &sum = rows.at(row, s);
                sum.volume += v.volume;
                sum.thickness += v.thickness;
                sum.cells += v.cells;
            }
    return rows;
}

std::vector<sbrt::ExpectedVolume> by_row(const Zones &zones,
                                         const std::vector<sbrt::ExpectedVolume> &expected)
{
    if (zones.counts_for.empty())
        return expected;
    std::vector<sbrt::ExpectedVolume> rows(zones.categories.size());
    for (size_t z = 0; z < expected.size(); ++z)
        for (int row : zones.counts_for[z]) {
            rows[size_t(row)].volume += expected[z].volume;
            rows[size_t(row)].cells += expected[z].cells;
        }
    return rows;
}

/// A region that misses the model (a new location's default region) gives
/// zeros: said, with how to set the region to the model.
void warn_when_no_cell_counts(const std::string &input, const sbrt::Frame &frame,
                              const sbrt::CellZones &in_region)
{
    const std::vector<int32_t> &zone = in_region.cell_zones();
    if (std::any_of(zone.begin(), zone.end(),
                    [](int32_t z) { return z != sbrt::CellZones::NO_ZONE; }))
        return;
    G_warning(_("The region holds no cell centre of SBRT <%s> (north %.15g, south %.15g, "
                "east %.15g, west %.15g): every volume is 0; set the region to the "
                "model with r3.sbrt.convert -s sbrt=%s, or with g.region"),
              input.c_str(), frame.north, frame.south, frame.east, frame.west,
              input.c_str());
}

} // namespace

void report_volumes(const VolumeRequest &request)
{
    // the output is checked before the model is read
    sbrt_grass::ReportFile out(request.output);
    struct Cell_head region;
    G_get_window(&region);
    const sbrt::MapArea area{region.north, region.south, region.east, region.west};
    // band by band within memory=; probability= reads the model whole (its
    // channels lie by the spans of every column)
    const bool whole = !request.probability.empty();
    sbrt_grass::SbrtBands bands(request.input, request.memory, request.threads, area, whole);
    const sbrt::Frame frame = bands.frame();
    const std::vector<sbrt::Material> &materials = bands.materials();

    VolumeReport report;
    report.input = request.input;
    report.units = G_database_unit_name(TRUE);
    report.materials = &materials;
    // classes= by id, code, short name or label (sbrt::ClassNames)
    report.sets = request.classes.empty()
                      ? sbrt::every_class(materials)
                      : std::vector<sbrt::ClassSet>{sbrt::ClassSet::of_materials(
                            materials, sbrt::ClassNames(materials)
                                           .resolve(request.classes, "classes",
                                                    "SBRT <" + request.input + ">"))};
    // the model's cells whose centre lies in the region, in an area where asked
    const sbrt::CellZones in_region = sbrt::CellZones::in_window(
        frame, {region.north, region.south, region.east, region.west, region.rows, region.cols});
    warn_when_no_cell_counts(request.input, frame, in_region);
    Zones zones{in_region, {}, {}};
    if (!request.areas.empty())
        zones = area_zones(frame, request.areas, request.layer, in_region);
    report.categories = zones.categories;

    sbrt::VolumeSums sums(frame, materials.size(), report.sets, zones.cells, request.threads);
    for (int row = 0; row < frame.rows; row = bands.band_end())
        sums.add_band(bands.band_at(row), row);
    G_verbose_message(_("Read in %d band(s), the largest %.1f MB in memory"),
                      bands.bands_read(), double(bands.largest_band_bytes()) / (1 << 20));
    const sbrt::VolumeTable table = by_row(zones, sums.table());
    if (whole) {
        const sbrt_grass::ProbabilityChannels p = sbrt_grass::read_probability_channels(
            request.input.c_str(), bands.band_at(0), request.probability, "probability=");
        report.probability = request.probability;
        report.expected =
            by_row(zones, sbrt::expected_volumes(bands.band_at(0), *p.channels, p.summed,
                                                 zones.cells.cell_zones(), zones.cells.zones()));
    }
    write_report(out.get(), request.format, request.separator, report, table);
    out.commit();
}
