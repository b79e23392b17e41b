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
#include <array>
#include <optional>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "location_units.hpp"
#include "log_writers.hpp"
#include "query_points.hpp"
#include "sbrt_choices.hpp"
#include "column_reading.hpp"
#include "sbrt_store.hpp"
#include "util/parallel.hpp"
#include "util/error.hpp"
#include "what_request.hpp"
#include "module_errors.hpp"
#include "report_file.hpp"

namespace {

/// The SBRT for the points' columns: paged within memory= (the blocks
/// read in order, each once), or the stacks of the points' cells alone,
/// decoded from the blocks that hold them (1000 points scattered over a
/// national model need about 4 in 10 of its blocks).
sbrt::Model read_model_under(const WhatRequest &request, const std::vector<QueryPoint> &points)
{
    std::vector<std::array<double, 2>> xy;
    for (const QueryPoint &p : points)
        xy.push_back({p.x, p.y});
    sbrt_grass::ColumnReading reading;
    reading.memory_bytes = request.memory_bytes;
    reading.threads = request.threads;
    reading.blocks_in_order = true; // (log_points)
    return sbrt_grass::read_sbrt_columns(request.input.c_str(), xy, reading);
}

/// The log of each point's column (with its voxels where `channels` are
/// given), on `threads` threads; a paged model's points taken block by
/// block, so that each block is decoded once.
std::vector<PointLog> log_points(const sbrt::Model &model, const std::vector<QueryPoint> &points,
                                 const sbrt::PropertyChannels *channels, unsigned threads)
{
    std::vector<std::optional<sbrt::GridCell>> cells(points.size());
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        cells[i] = sbrt::cell_of_point(model.frame(), points[i].x, points[i].y);
        order[i] = i;
    }
    if (const sbrt::StackPages *pages = model.pages()) {
        const auto block = [&](size_t i) {
            return cells[i] ? pages->block_of(cells[i]->row, cells[i]->col) : -1;
        };
        std::stable_sort(order.begin(), order.end(),
                         [&](size_t a, size_t b) { return block(a) < block(b); });
    }
    // runs of points in one block, each run taken by one thread: a block
    // is decoded once (a model decoded whole: a point a run)
    std::vector<size_t> run_starts;
    const auto block_at = [&](size_t k) {
        const std::optional<sbrt::GridCell> &c = cells[order[k]];
        return model.pages() && c ? model.pages()->block_of(c->row, c->col) : -1;
    };
    for (size_t k = 0; k < order.size(); ++k)
        if (k == 0 || block_at(k) != block_at(k - 1) || !model.pages())
            run_starts.push_back(k);
    run_starts.push_back(order.size());
    std::vector<PointLog> logs(points.size());
    sbrt::for_each_row(int(run_starts.size()) - 1, threads, [&](int run) {
        for (size_t k = run_starts[size_t(run)]; k < run_starts[size_t(run) + 1]; ++k) {
            const size_t i = order[k];
            logs[i].point = points[i];
            if (cells[i]) {
                logs[i].log = sbrt::column_log(model, *cells[i]);
                if (channels)
                    logs[i].voxels = sbrt::column_voxels(model, *channels, *cells[i]);
            }
        }
    });
    return logs;
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
    const sbrt::Model model = read_model_under(request, points);
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
    const std::vector<PointLog> logs = log_points(model, points, channels.get(), request.threads);
    sbrt_grass::report_paging(model);
    const size_t outside = size_t(
        std::count_if(logs.begin(), logs.end(), [](const PointLog &l) { return !l.log; }));
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
