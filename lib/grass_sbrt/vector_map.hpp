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
    /// `layer`: as Vect_open_old2 takes it ("-1" for every layer).
    VectorMap(const std::string &name, const char *layer);
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

} // namespace sbrt_grass

#endif
