/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   Reads the SBRT, counts the model cells of the region (or of
 *            each area), measures the volumes and writes the report
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cerrno>
#include <cstring>

#include "sbrt_store.hpp"
#include "util/error.hpp"
#include "volume.hpp"

namespace {

/// \brief The report's file, standard output for "" and "-".
class OutputFile {
public:
    explicit OutputFile(const std::string &name)
    {
        if (name.empty() || name == "-")
            return;
        file_ = std::fopen(name.c_str(), "w");
        if (!file_)
            sbrt::fail("output=", name, ": cannot write the file (", std::strerror(errno), ")");
    }
    ~OutputFile()
    {
        if (file_)
            std::fclose(file_);
    }
    OutputFile(const OutputFile &) = delete;
    OutputFile &operator=(const OutputFile &) = delete;
    FILE *get() const { return file_ ? file_ : stdout; }
    void close(const std::string &name)
    {
        if (file_ && std::fclose(file_) != 0) {
            file_ = nullptr;
            sbrt::fail("output=", name, ": writing the file failed (", std::strerror(errno),
                       ")");
        }
        file_ = nullptr;
    }

private:
    FILE *file_ = nullptr;
};

} // namespace

void report_volumes(const VolumeRequest &request)
{
    // the output is checked before the model is read
    OutputFile out(request.output);
    struct Cell_head region;
    G_get_window(&region);
    sbrt::ReadOptions options;
    options.threads = request.threads;
    options.area = sbrt::MapArea{region.north, region.south, region.east, region.west};
    const sbrt::Model model = sbrt_grass::read_sbrt_map(request.input.c_str(), options);

    VolumeReport report;
    report.input = request.input;
    report.units = G_database_unit_name(TRUE);
    report.model = &model;
    report.sets = request.classes.empty()
                      ? sbrt::every_class(model)
                      : std::vector<sbrt::ClassSet>{sbrt::ClassSet::named(model, request.classes)};
    // the model's cells whose centre lies in the region, in an area where asked
    const sbrt::CellZones in_region = sbrt::CellZones::in_window(
        model.frame(),
        {region.north, region.south, region.east, region.west, region.rows, region.cols});
    Zones zones{in_region, {}};
    if (!request.areas.empty())
        zones = area_zones(model, request.areas, request.layer, in_region);
    report.categories = zones.categories;

    const sbrt::VolumeTable table =
        sbrt::measure_volumes(model, report.sets, zones.cells, request.threads);
    if (!request.probability.empty()) {
        const sbrt_grass::ProbabilityChannels p = sbrt_grass::read_probability_channels(
            request.input.c_str(), model, request.probability, "probability=");
        report.probability = request.probability;
        report.expected = sbrt::expected_volumes(model, *p.channels, p.summed,
                                                 zones.cells.cell_zones(), zones.cells.zones());
    }
    write_report(out.get(), request.format, report, table);
    out.close(request.output);
}
