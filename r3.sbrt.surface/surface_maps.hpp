/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * PURPOSE:   The output maps: opened together, written row by row, closed
 *            with title, units, vertical datum, history and a colour table
 *            that suits each
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SURFACE_MAPS_HPP
#define R3_SBRT_SURFACE_MAPS_HPP

#include <string>
#include <vector>

#include "grass.hpp"
#include "measure/column_figures.hpp"
#include "raster_metadata.hpp"
#include "surface.hpp"

/// \brief The maps a request asks for, in the current region.
class SurfaceMaps {
public:
    /// Makes the maps' metadata (titles and history: `set` describes the
    /// class set, "1 (Sand), 2 (Clay)"; `datum` is the model's vertical
    /// datum, "NAP" or empty), then opens the maps (fatal error where one
    /// cannot be opened).
    SurfaceMaps(const SurfaceRequest &request, const std::string &set,
                const std::string &datum, int cols);
    SurfaceMaps(const SurfaceMaps &) = delete;
    SurfaceMaps &operator=(const SurfaceMaps &) = delete;
    /// Closes maps left open (an error on the way): they are not kept.
    ~SurfaceMaps();

    /// The next row: figures of each cell, null where !present[col]; the
    /// expected thickness of each (NaN: null), where it is asked for.
    void put_row(const sbrt::MapFigures *figures, const unsigned char *present,
                 const double *expected);
    /// Closes the maps and writes their metadata.
    void close();

private:
    enum class Figure { top, base, thickness, layers, depth, expected };
    struct Map {
        Figure figure = Figure::top;
        std::string name;
        int fd = -1;
        std::string title, units;      ///< cut to what GRASS keeps
        std::string vertical_datum;    ///< of elevations and depths; empty: none
        sbrt_grass::MapHistory history;
        const char *colors = "";       ///< GRASS colour rules, over the range
        bool colors_from_zero = false; ///< the range from 0
    };
    static double value(Figure figure, const sbrt::MapFigures &f);
    /// Map `name` of `figure` with its metadata, not yet open.
    static Map metadata(Figure figure, const std::string &name, const SurfaceRequest &request,
                        const std::string &set, const std::string &datum);

    int cols_;
    std::vector<Map> maps_;
    std::vector<DCELL> dcells_;
    std::vector<CELL> cells_;
    bool open_ = false;
};

#endif
