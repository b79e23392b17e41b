/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   A vector map open for reading feature by feature (RAII), for
 *            the modules that take points or lines
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_VECTOR_MAP_HPP
#define SBRT_VECTOR_MAP_HPP

#include <string>

#include "grass.hpp"

extern "C" {
#include <grass/vector.h>
}

namespace sbrt_grass {

/// \brief An open vector map at level 1 (no topology needed), closed on
/// scope exit. A missing or unreadable map throws sbrt::Error (the view
/// server answers it and goes on; Vect_open_old2 itself would end the
/// process).
class VectorMap {
public:
    /// `layer`: as Vect_open_old2 takes it ("-1" for every layer);
    /// `option`: the option that names the map, for the message (none: no
    /// option named).
    VectorMap(const std::string &name, const char *layer, const char *option = nullptr);
    ~VectorMap();
    VectorMap(const VectorMap &) = delete;
    VectorMap &operator=(const VectorMap &) = delete;

    /// The next feature's type (0 at the end); its points and categories.
    int next();
    const line_pnts &points() const { return *points_; }
    line_cats *cats() { return cats_; }
    Map_info &map() { return map_; }

private:
    Map_info map_;
    line_pnts *points_;
    line_cats *cats_;
};

/// The layer number that `layer` (a layer= option's answer) names in
/// `map`: a number as it is (-1: every layer), else the name of one of the
/// map's layers (its database links, as v.db.connect -p lists them).
/// Vect_get_field_number would take any other text as layer 0 (atoi);
/// GRASS's modules refuse such a layer, and so does this (sbrt::Error).
int layer_number(Map_info &map, const std::string &layer);

} // namespace sbrt_grass

#endif
