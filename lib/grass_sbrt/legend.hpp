/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Material legends <-> GRASS colour tables and categories
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_LEGEND_HPP
#define SBRT_LEGEND_HPP

#include <vector>

#include "grass.hpp"
#include "model/model.hpp"

namespace sbrt_grass {

/// Fills label and colour of `materials` from a 3D raster's cats and colr.
void read_raster3d_legend(const char *name, const char *mapset,
                          std::vector<sbrt::Material> &materials);
/// A colour table with one rule per material (index 0 skipped): its own
/// colour, else the default palette's, as a render draws it.
void make_colors(const std::vector<sbrt::Material> &materials,
                 struct Colors *colors);
/// Category labels of the materials, titled `title`, each cut to what
/// GRASS reads back (raster_metadata.hpp).
void make_cats(const std::vector<sbrt::Material> &materials,
               struct Categories *cats, const char *title);

/// Gives raster map `name` of the current mapset (class ids) the
/// materials' colours (make_colors) and labels (make_cats), and the title
/// `title` with them.
void write_class_legend(const char *name, const std::vector<sbrt::Material> &materials,
                        const char *title);

} // namespace sbrt_grass

#endif
