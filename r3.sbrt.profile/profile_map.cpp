/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The class profile as a raster map
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "profile_map.hpp"

#include <cmath>
#include <vector>

#include "legend.hpp"
#include "raster_metadata.hpp"

int profile_columns(double length, double step)
{
    const double cols = std::round(length / step);
    if (cols > 1e6)
        G_fatal_error(_("The profile map would have %.0f columns along the %g map units of the "
                        "line: give a larger resolution="),
                      cols, length);
    return std::max(1, int(cols));
}

std::optional<ProfileGrid> profile_grid(const sbrt::Model &model, const sbrt::ProfileLine &line,
                                        int cols)
{
    const auto solid = sbrt::solid_extent(model, line, cols);
    if (!solid)
        return std::nullopt;
    // whole layers: the rows are the model's own levels
    const sbrt::Frame &f = model.frame();
    const double low = std::floor(f.local_z(solid->bottom) + 1e-9);
    const double high = std::ceil(f.local_z(solid->top) - 1e-9);
    ProfileGrid grid;
    grid.cols = cols;
    grid.rows = std::max(1, int(high - low));
    grid.extent = {f.bottom + low * f.tb_res(), f.bottom + (low + grid.rows) * f.tb_res()};
    return grid;
}

struct Cell_head profile_window(const ProfileGrid &grid, double length)
{
    struct Cell_head window;
    G_get_window(&window); // projection, zone and the 3D part as they are
    window.west = 0;
    window.east = length;
    window.south = grid.extent.bottom;
    window.north = grid.extent.top;
    window.rows = window.rows3 = grid.rows;
    window.cols = window.cols3 = grid.cols;
    window.ew_res = window.ew_res3 = length / grid.cols;
    window.ns_res = window.ns_res3 = (grid.extent.top - grid.extent.bottom) / grid.rows;
    G_adjust_Cell_head(&window, 1, 1);
    return window;
}

void write_profile_map(const std::string &name, const sbrt::ClassProfile &profile,
                       const sbrt::Model &model, const std::string &input,
                       const std::string &line_text)
{
    // the metadata made first, cut to what GRASS keeps (a line of many
    // vertices makes a long title), so that nothing fails once the map's
    // rows are written
    const std::string title =
        sbrt_grass::metadata_line("Profile of " + input + " along " + line_text,
                                  sbrt_grass::MAX_TITLE_BYTES);
    sbrt_grass::MapHistory history;
    history.data_source_1 = "SBRT " + input;
    history.keywords = "x: distance along the line, y: elevation";

    ProfileGrid grid{profile.rows, profile.cols, profile.extent};
    struct Cell_head window = profile_window(grid, profile.length);
    Rast_set_output_window(&window);
    const int fd = Rast_open_new(name.c_str(), CELL_TYPE);
    std::vector<CELL> row(size_t(profile.cols));
    for (int r = 0; r < profile.rows; ++r) {
        for (int c = 0; c < profile.cols; ++c) {
            const int32_t id = profile.at(r, c);
            if (id == sbrt::NULL_CLASS)
                Rast_set_c_null_value(&row[size_t(c)], 1);
            else
                row[size_t(c)] = id;
        }
        Rast_put_c_row(fd, row.data());
    }
    Rast_close(fd);
    // the title goes with the labels, in one write of the cats file
    sbrt_grass::write_class_legend(name.c_str(), model.materials(), title.c_str());
    sbrt_grass::write_raster_history(name.c_str(), history);
}
