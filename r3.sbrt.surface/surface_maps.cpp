/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * PURPOSE:   The output maps with title, units, vertical datum, history and
 *            colours (as r.series writes its maps)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "surface_maps.hpp"

#include <cmath>

#include "location_units.hpp"
#include "raster_metadata.hpp"

namespace {

/// Colour table `rules` over the map's range, from `low` where given.
void write_colors(const std::string &name, const char *rules, bool from_zero, bool integer)
{
    const char *mapset = G_mapset();
    DCELL min = 0, max = 1;
    if (integer) {
        struct Range range;
        Rast_read_range(name.c_str(), mapset, &range);
        CELL cmin, cmax;
        Rast_get_range_min_max(&range, &cmin, &cmax);
        if (!Rast_is_c_null_value(&cmin)) {
            min = cmin;
            max = cmax;
        }
    }
    else {
        struct FPRange range;
        Rast_read_fp_range(name.c_str(), mapset, &range);
        Rast_get_fp_range_min_max(&range, &min, &max);
        if (Rast_is_d_null_value(&min)) {
            min = 0;
            max = 1;
        }
    }
    if (from_zero)
        min = 0;
    if (!(max > min))
        max = min + 1;
    struct Colors colors;
    Rast_init_colors(&colors);
    Rast_make_fp_colors(&colors, rules, min, max);
    Rast_write_colors(name.c_str(), mapset, &colors);
    Rast_free_colors(&colors);
}

/// What a depth map's vertical datum says (r.info: "Vertical datum: model
/// surface"): depths are measured down from the model's surface (the top
/// of each column's highest layer), not from the datum of its elevations.
constexpr const char *DEPTH_DATUM = "model surface";

} // namespace

SurfaceMaps::SurfaceMaps(const SurfaceRequest &request, const std::string &set,
                         const std::string &datum, int cols)
    : cols_(cols), dcells_(size_t(cols)), cells_(size_t(cols))
{
    const std::pair<Figure, const std::string *> asked[] = {
        {Figure::top, &request.top},
        {Figure::base, &request.base},
        {Figure::thickness, &request.thickness},
        {Figure::layers, &request.layers},
        {Figure::depth, &request.depth},
        {Figure::expected, &request.expected_thickness}};
    for (const auto &[figure, name] : asked)
        if (!name->empty()) {
            // the metadata first: nothing is left to fail once rows are written
            Map map = metadata(figure, *name, request, set, datum);
            map.fd = Rast_open_new(name->c_str(),
                                   figure == Figure::layers ? CELL_TYPE : DCELL_TYPE);
            maps_.push_back(std::move(map));
        }
    open_ = true;
}

SurfaceMaps::~SurfaceMaps()
{
    if (open_)
        for (const Map &map : maps_)
            Rast_unopen(map.fd);
}

double SurfaceMaps::value(Figure figure, const sbrt::MapFigures &f)
{
    switch (figure) {
    case Figure::top:
        return f.top;
    case Figure::base:
        return f.base;
    case Figure::thickness:
        return f.thickness;
    case Figure::layers:
        return f.layers;
    case Figure::depth:
        return f.depth;
    case Figure::expected:
        break; // not a figure of the class set
    }
    return 0;
}

void SurfaceMaps::put_row(const sbrt::MapFigures *figures, const unsigned char *present,
                          const double *expected)
{
    for (const Map &map : maps_) {
        if (map.figure == Figure::expected) {
            for (int c = 0; c < cols_; ++c)
                if (std::isnan(expected[c]))
                    Rast_set_d_null_value(&dcells_[size_t(c)], 1);
                else
                    dcells_[size_t(c)] = expected[c];
            Rast_put_d_row(map.fd, dcells_.data());
            continue;
        }
        if (map.figure == Figure::layers) {
            for (int c = 0; c < cols_; ++c)
                if (present[c])
                    cells_[size_t(c)] = CELL(figures[c].layers);
                else
                    Rast_set_c_null_value(&cells_[size_t(c)], 1);
            Rast_put_c_row(map.fd, cells_.data());
            continue;
        }
        for (int c = 0; c < cols_; ++c)
            if (present[c])
                dcells_[size_t(c)] = value(map.figure, figures[c]);
            else
                Rast_set_d_null_value(&dcells_[size_t(c)], 1);
        Rast_put_d_row(map.fd, dcells_.data());
    }
}

void SurfaceMaps::close()
{
    for (const Map &map : maps_)
        Rast_close(map.fd);
    open_ = false;
    for (const Map &map : maps_) {
        write_colors(map.name, map.colors, map.colors_from_zero, map.figure == Figure::layers);
        sbrt_grass::put_raster_title(map.name.c_str(), map.title);
        sbrt_grass::write_raster_units(map.name.c_str(), map.units);
        if (!map.vertical_datum.empty())
            Rast_write_vdatum(map.name.c_str(), map.vertical_datum.c_str());
        sbrt_grass::write_raster_history(map.name.c_str(), map.history);
    }
}

SurfaceMaps::Map SurfaceMaps::metadata(Figure figure, const std::string &name,
                                       const SurfaceRequest &request, const std::string &set,
                                       const std::string &datum)
{
    Map map;
    map.figure = figure;
    map.name = name;
    const char *what = "";
    switch (figure) {
    case Figure::top:
        what = "Elevation of the top";
        map.colors = "elevation";
        break;
    case Figure::base:
        what = "Elevation of the base";
        map.colors = "elevation";
        break;
    case Figure::thickness:
        what = "Thickness";
        map.colors = "viridis";
        map.colors_from_zero = true;
        break;
    case Figure::layers:
        what = "Number of layers";
        map.colors = "bcyr";
        break;
    case Figure::depth:
        what = "Depth below the model's surface of the top";
        map.colors = "blues";
        map.colors_from_zero = true;
        break;
    case Figure::expected:
        what = "Expected thickness";
        map.colors = "viridis";
        map.colors_from_zero = true;
        break;
    }
    const std::string of =
        figure == Figure::expected ? "probability " + request.probability : set;
    // elevations with their unit and datum: "Elevation (m NAP) of the top"
    const std::string unit = sbrt_grass::location_length_unit();
    std::string described = what;
    if (figure == Figure::top || figure == Figure::base)
        described.insert(std::string("Elevation").size(),
                         " (" + unit + (datum.empty() ? "" : " " + datum) + ")");
    // the class labels can make these long: cut to what GRASS keeps
    map.title = sbrt_grass::metadata_line(
        described + " of " + of + " in SBRT " + request.input,
        sbrt_grass::MAX_TITLE_BYTES);
    map.units = figure == Figure::layers ? "layers" : unit;
    // elevations relative to the model's datum (another mapset's text: one
    // printable line); depths from the model's surface; thicknesses and
    // counts have none
    if (figure == Figure::top || figure == Figure::base)
        map.vertical_datum = sbrt_grass::metadata_line(datum, sbrt_grass::MAX_UNITS_BYTES);
    else if (figure == Figure::depth)
        map.vertical_datum = DEPTH_DATUM;
    map.history.data_source_1 = "SBRT " + request.input;
    map.history.data_source_2 = (figure == Figure::expected ? "" : "classes ") + of;
    return map;
}
