/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   A geological profile of an SBRT along a line: the classes the
 *            vertical section cuts as a raster map (distance along the line
 *            by elevation) and as a figure with axes, the classes' legend,
 *            the vertical exaggeration and a location map
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "line_input.hpp"
#include "model/material_table.hpp"
#include "module_errors.hpp"
#include "profile_figure.hpp"
#include "profile_map.hpp"
#include "output_format.hpp"
#include "profile_request.hpp"
#include "sbrt_choices.hpp"
#include "column_reading.hpp"
#include "sbrt_store.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace {

using Json = nlohmann::ordered_json;

AxisUnits axis_units(const std::string &datum)
{
    AxisUnits u;
    u.datum = datum;
    if (G_projection() == PROJECTION_XY) {
        u.length = "map units";
        u.metres = false;
    }
    else if (G_database_units_to_meters_factor() != 1.0) {
        u.length = G_database_unit_name(TRUE);
        u.metres = false;
    }
    return u;
}

/// "A (x y) - B (x y)": the line as the map's title and history give it.
std::string line_text(const sbrt::ProfileLine &line)
{
    std::string text;
    for (size_t k = 0; k < line.vertices().size(); ++k) {
        char point[96];
        std::snprintf(point, sizeof point, "%s%s (%.10g %.10g)", k ? " - " : "",
                      vertex_name(k).c_str(), line.vertices()[k].x, line.vertices()[k].y);
        text += point;
    }
    return text;
}

/// The frame of SBRT `input` alone: no block is decoded.
sbrt::Frame read_frame(const std::string &input)
{
    sbrt::ReadOptions options;
    options.points.emplace(); // no points: no stacks
    return sbrt_grass::read_sbrt_map(input.c_str(), options).frame();
}

/// The SBRT (its frame: `frame`) for the columns under the line's samples
/// (`columns` of each count) and the location map's samples: paged within
/// memory=, or those stacks alone, read from the blocks that hold them.
sbrt::Model read_model_along(const ProfileRequest &request, const sbrt::Frame &frame,
                             const sbrt::ProfileLine &line, const std::vector<int> &columns)
{
    std::vector<std::array<double, 2>> points;
    for (int cols : columns)
        for (int c = 0; c < cols; ++c) {
            const glm::dvec2 p = line.column_point(c, cols);
            points.push_back({p.x, p.y});
        }
    for (const glm::dvec2 &p : location_samples(frame, line, request.width))
        points.push_back({p.x, p.y});
    sbrt_grass::ColumnReading reading;
    reading.memory_bytes = request.memory_bytes;
    reading.threads = request.threads;
    // (the line is walked more than once: the blocks stay while they fit;
    // the figure's location map reads the stored column ranges)
    reading.tops_map = !request.png.empty();
    return sbrt_grass::read_sbrt_columns(request.input.c_str(), points, reading);
}

std::string joined(const std::vector<double> &values)
{
    std::string text;
    for (double v : values) {
        char number[32];
        std::snprintf(number, sizeof number, "%s%.10g", text.empty() ? "" : ",", v + 0.0);
        text += number;
    }
    return text;
}

void print_shell(const sbrt::ProfileLine &line, const std::optional<ProfileGrid> &grid,
                 const FigureAxes &axes, const AxisUnits &units, const FigureLayout &layout)
{
    std::printf("length=%.10g\n", line.length());
    std::printf("vertex_distances=%s\n", joined(line.vertex_distances()).c_str());
    if (grid) {
        const struct Cell_head w = profile_window(*grid, line.length());
        std::printf("map_west=%.10g\nmap_east=%.10g\nmap_south=%.10g\nmap_north=%.10g\n"
                    "map_rows=%d\nmap_cols=%d\nmap_ewres=%.10g\nmap_nsres=%.10g\n",
                    w.west, w.east, w.south, w.north, w.rows, w.cols, w.ew_res, w.ns_res);
    }
    std::printf("zexag=%g\n", axes.zexag);
    std::printf("figure_width=%d\nfigure_height=%d\n", layout.width, layout.height);
    std::printf("plot_left=%d\nplot_top=%d\nplot_width=%d\nplot_height=%d\n", layout.plot_left,
                layout.plot_top, axes.plot_width, axes.plot_height);
    std::printf("plot_bottom=%.10g\nplot_top_elevation=%.10g\n", axes.extent.bottom,
                axes.extent.top);
    std::printf("elevation_ticks=%s\n", joined(axes.elevation_ticks).c_str());
    std::printf("distance_ticks=%s\n", joined(axes.distance_ticks).c_str());
    std::vector<double> rows, columns;
    for (double t : axes.elevation_ticks)
        rows.push_back(layout.plot_top + std::round(axes.y_of(t)));
    for (double t : axes.distance_ticks)
        columns.push_back(layout.plot_left + std::round(axes.x_of(t)));
    std::printf("elevation_tick_rows=%s\n", joined(rows).c_str());
    std::printf("distance_tick_columns=%s\n", joined(columns).c_str());
    // text (the datum comes from the model's file) as one shell word each
    std::printf("distance_unit=%s\n", sbrt::shell_word(axes.distance_unit).c_str());
    std::printf("elevation_title=%s\n", sbrt::shell_word(elevation_title(units)).c_str());
    // the titles as the figure draws them: fitted to its width
    std::printf("title=%s\n", sbrt::shell_word(layout.title).c_str());
    std::printf("distance_title=%s\n", sbrt::shell_word(layout.distance_title).c_str());
    std::string lettered;
    for (size_t k : layout.lettered)
        lettered += (lettered.empty() ? "" : ",") + std::to_string(k);
    std::printf("lettered_vertices=%s\n", lettered.c_str());
    std::string cut;
    for (int32_t id : layout.classes_cut)
        cut += (cut.empty() ? "" : ",") + std::to_string(id);
    std::printf("classes_cut=%s\n", cut.c_str());
    // (a failed write fails the module in run_reporting_errors)
}

/// `values` as a json array, -0 as 0 (as joined writes them).
Json json_numbers(const std::vector<double> &values)
{
    Json list = Json::array();
    for (double v : values)
        list.push_back(v + 0.0);
    return list;
}

/// format=json: print_shell's keys, numbers as numbers and lists as
/// arrays, through nlohmann::json (the titles and the datum are valid UTF-8
/// whatever the model's file holds).
void print_json(const sbrt::ProfileLine &line, const std::optional<ProfileGrid> &grid,
                const FigureAxes &axes, const AxisUnits &units, const FigureLayout &layout)
{
    Json p;
    p["length"] = line.length();
    p["vertex_distances"] = json_numbers(line.vertex_distances());
    if (grid) {
        const struct Cell_head w = profile_window(*grid, line.length());
        p["map_west"] = w.west;
        p["map_east"] = w.east;
        p["map_south"] = w.south;
        p["map_north"] = w.north;
        p["map_rows"] = w.rows;
        p["map_cols"] = w.cols;
        p["map_ewres"] = w.ew_res;
        p["map_nsres"] = w.ns_res;
    }
    p["zexag"] = axes.zexag;
    p["figure_width"] = layout.width;
    p["figure_height"] = layout.height;
    p["plot_left"] = layout.plot_left;
    p["plot_top"] = layout.plot_top;
    p["plot_width"] = axes.plot_width;
    p["plot_height"] = axes.plot_height;
    p["plot_bottom"] = axes.extent.bottom;
    p["plot_top_elevation"] = axes.extent.top;
    p["elevation_ticks"] = json_numbers(axes.elevation_ticks);
    p["distance_ticks"] = json_numbers(axes.distance_ticks);
    Json rows = Json::array(), columns = Json::array();
    for (double t : axes.elevation_ticks)
        rows.push_back(int(layout.plot_top + std::round(axes.y_of(t))));
    for (double t : axes.distance_ticks)
        columns.push_back(int(layout.plot_left + std::round(axes.x_of(t))));
    p["elevation_tick_rows"] = rows;
    p["distance_tick_columns"] = columns;
    p["distance_unit"] = axes.distance_unit;
    p["elevation_title"] = elevation_title(units);
    p["title"] = layout.title;
    p["distance_title"] = layout.distance_title;
    p["lettered_vertices"] = layout.lettered;
    p["classes_cut"] = layout.classes_cut;
    std::printf("%s\n", sbrt_grass::json_text(p).c_str());
}

void run(const ProfileRequest &request)
{
    if (G_projection() == PROJECTION_LL)
        sbrt_grass::fail_with(
            _("A profile measures distances along its line in map units, which a "
              "latitude-longitude location does not have: use a projected "
              "location"));
    const sbrt::ProfileLine line(read_line_vertices(request));
    // the map's columns at its step (the model's finer resolution unless given)
    const sbrt::Frame frame = read_frame(request.input);
    const double step =
        request.resolution.value_or(std::min(frame.ew_res(), frame.ns_res()));
    const int map_cols = profile_columns(line.length(), step);
    const sbrt::Model model = read_model_along(request, frame, line, {map_cols, request.width});

    const std::optional<ProfileGrid> grid = profile_grid(model, line, map_cols);
    auto solid = sbrt::solid_extent(model, line, request.width);
    if (!solid && grid)
        solid = grid->extent;
    if (!solid)
        sbrt_grass::fail_with(
            _("The line meets no layer of SBRT <%s> (%s; the model covers %g to %g "
              "east, %g to %g north)"),
            request.input.c_str(), line_text(line).c_str(), frame.west, frame.east, frame.south,
            frame.north);
    if (!request.output.empty()) {
        const ProfileGrid g = grid ? *grid : ProfileGrid{1, map_cols, *solid};
        const sbrt::ClassProfile profile =
            sbrt::class_profile(model, line, g.cols, g.rows, g.extent);
        write_profile_map(request.output, profile, model, request.input, line_text(line));
        G_verbose_message(_("Profile map <%s>: %d columns of %g along the line, %d rows of %g"),
                          request.output.c_str(), g.cols, line.length() / g.cols, g.rows,
                          (g.extent.top - g.extent.bottom) / g.rows);
    }
    const AxisUnits units = axis_units(model.vertical_datum());
    const FigureAxes axes = figure_axes(line.length(), *solid, request.zexag, request.width, units);
    if (axes.zexag_fitted && !request.png.empty())
        G_message(_("Vertical exaggeration %g, fitted to the line (%.6g %s long, layers "
                    "%.6g %s thick; give zexag= to choose another)"),
                  axes.zexag, line.length(), units.length.c_str(), solid->top - solid->bottom,
                  units.length.c_str());
    if (request.png.empty() && request.print == sbrt_grass::OutputFormat::none) {
        sbrt_grass::report_paging(model);
        return;
    }
    FigureContent content;
    content.title = "Profile " + line_name(line.vertices().size()) + " of " + request.input;
    content.short_title =
        "Profile " + short_line_name(line.vertices().size()) + " of " + request.input;
    content.model = &model;
    content.line = &line;
    content.units = units;
    for (uint32_t m = 1; m < model.materials().size(); ++m)
        content.classes.push_back({model.materials()[m].id, model.materials()[m].label,
                                   sbrt::material_color(model, m)});
    const sbrt::ClassProfile plot =
        sbrt::class_profile(model, line, axes.plot_width, axes.plot_height, axes.extent);
    const FigureLayout layout = draw_profile_figure(axes, plot, content, request.png);
    sbrt_grass::report_paging(model);
    if (request.print == sbrt_grass::OutputFormat::shell)
        print_shell(line, grid, axes, units, layout);
    else if (request.print == sbrt_grass::OutputFormat::json)
        print_json(line, grid, axes, units, layout);
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("profile"));
    G_add_keyword(_("cross section"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("SBRT"));
    module->label = _("Draws a geological profile of an SBRT along a line.");
    module->description =
        _("Writes the classes that the vertical section under a straight or bent line cuts "
          "as a raster map (distance by elevation) and as a figure with axes, legend and "
          "location map.");
    const ProfileOptions options = define_profile_options();
    sbrt_grass::offer_sbrts_in_dialog(options.input, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const ProfileRequest request = read_profile_request(options);
    sbrt_grass::run_reporting_errors("drawing the profile of SBRT", request.input,
                                     _("give a larger resolution= or a smaller width="),
                                     [&] { run(request); });
    exit(EXIT_SUCCESS);
}
