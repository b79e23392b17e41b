/****************************************************************************
 * MODULE:    r3.sbrt.what
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Logs the column of an SBRT under points, as r.what queries
 *            rasters: every layer top to bottom with its class, label,
 *            top, bottom and thickness at the model's heights with their
 *            datum, and depths below the surface (a virtual borehole)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "location_units.hpp"
#include "log_writers.hpp"
#include "query_points.hpp"
#include "sbrt_choices.hpp"
#include "sbrt_store.hpp"
#include "util/error.hpp"
#include "what_request.hpp"
#include "module_errors.hpp"
#include "report_file.hpp"

namespace {

/// The SBRT with only the stacks of the points' cells, decoded from the
/// blocks that hold them (1000 points scattered over a national model
/// need about 4 in 10 of its blocks, and no other cell's intervals).
sbrt::Model read_model_under(const std::string &name, const std::vector<QueryPoint> &points,
                             unsigned threads)
{
    sbrt::ReadOptions options;
    options.threads = threads;
    sbrt::ReadReport report;
    options.report = &report;
    options.points.emplace();
    for (const QueryPoint &p : points)
        options.points->push_back({p.x, p.y});
    sbrt::Model model = sbrt_grass::read_sbrt_map(name.c_str(), options);
    if (report.blocks)
        G_verbose_message(_("Read %llu of the %llu blocks of SBRT <%s>"),
                          (unsigned long long)report.blocks_read,
                          (unsigned long long)report.blocks, name.c_str());
    return model;
}

/// Writes the logs to output= (standard output where it is empty or "-").
void write_logs(const WhatRequest &request, const LogSource &source,
                const std::vector<PointLog> &logs)
{
    sbrt_grass::ReportFile out(request.output);
    if (request.format == LogFormat::json)
        write_json_logs(out.get(), source, logs);
    else if (request.format == LogFormat::csv)
        write_csv_logs(out.get(), source, logs);
    else
        write_plain_logs(out.get(), source, logs);
    // a full disk shows in the flush or the close: the logs are
    // incomplete, which must not end with status 0 nor leave a file
    // (standard output is checked for every module by run_reporting_errors)
    out.commit();
}

void run(const WhatRequest &request)
{
    const std::vector<QueryPoint> points = query_points(request);
    const sbrt::Model model = read_model_under(request.input, points, request.threads);
    // the property channels, where the model has them and the output
    // shows them (json always, plain and csv with -v): only the blocks
    // under the points are decoded
    const bool show_voxels = request.voxels || request.format == LogFormat::json;
    const auto channels = show_voxels
                              ? sbrt_grass::read_channels_map(request.input.c_str(), model)
                              : nullptr;
    LogSource source{model, {}};
    source.elevation_unit = sbrt_grass::location_length_unit();
    source.voxel_rows = request.voxels;
    source.separator = request.separator;
    if (channels)
        source.channels = channels->infos();
    std::vector<PointLog> logs(points.size());
    size_t outside = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        logs[i].point = points[i];
        if (const auto cell = sbrt::cell_of_point(model.frame(), points[i].x, points[i].y)) {
            logs[i].log = sbrt::column_log(model, *cell);
            if (channels)
                logs[i].voxels = sbrt::column_voxels(model, *channels, *cell);
        }
        else
            ++outside;
    }
    if (outside)
        G_verbose_message(_("%zu of %zu points lie outside SBRT <%s>"), outside,
                          points.size(), request.input.c_str());
    write_logs(request, source, logs);
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("querying"));
    G_add_keyword(_("position"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("borehole"));
    G_add_keyword(_("SBRT"));
    module->label = _("Logs the column of an SBRT under points (virtual boreholes).");
    module->description =
        _("Lists every layer of a stack-based terrain model (SBRT) under the "
          "given points, top to bottom, with class, label, top, bottom and "
          "thickness at the model's heights (with their vertical datum) and "
          "depths below the surface, and the property channels voxel by voxel "
          "where the model has them.");
    const WhatOptions options = define_what_options();
    sbrt_grass::offer_sbrts_in_dialog(options.input, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const WhatRequest request = read_what_request(options);
    sbrt_grass::run_reporting_errors("reading SBRT", request.input,
                                     _("ask for fewer points at a time"),
                                     [&] { run(request); });
    exit(EXIT_SUCCESS);
}
