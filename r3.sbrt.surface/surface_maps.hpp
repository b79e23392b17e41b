/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * PURPOSE:   The output maps: opened together, written row by row, closed
 *            with title, units, history and a colour table that suits each
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SURFACE_MAPS_HPP
#define R3_SBRT_SURFACE_MAPS_HPP

#include <string>
#include <vector>

#include "grass.hpp"
#include "measure/column_figures.hpp"
#include "surface.hpp"

/// \brief The maps a request asks for, in the current region.
class SurfaceMaps {
public:
    /// Opens the maps (fatal error where one cannot be opened).
    SurfaceMaps(const SurfaceRequest &request, int cols);
    SurfaceMaps(const SurfaceMaps &) = delete;
    SurfaceMaps &operator=(const SurfaceMaps &) = delete;
    /// Closes maps left open (an error on the way): they are not kept.
    ~SurfaceMaps();

    /// The next row: figures of each cell, null where !present[col]; the
    /// expected thickness of each (NaN: null), where it is asked for.
    void put_row(const sbrt::MapFigures *figures, const unsigned char *present,
                 const double *expected);
    /// Closes the maps and writes their metadata; `set` describes the class
    /// set ("1 (Sand), 2 (Clay)").
    void close(const SurfaceRequest &request, const std::string &set);

private:
    enum class Figure { top, base, thickness, layers, depth, expected };
    struct Map {
        Figure figure;
        std::string name;
        int fd;
    };
    static double value(Figure figure, const sbrt::MapFigures &f);
    void write_metadata(const Map &map, const SurfaceRequest &request,
                        const std::string &set) const;

    int cols_;
    std::vector<Map> maps_;
    std::vector<DCELL> dcells_;
    std::vector<CELL> cells_;
    bool open_ = false;
};

#endif
