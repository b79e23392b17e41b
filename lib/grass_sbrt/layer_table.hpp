/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The attribute table of a vector map's layer, and the
 *            categories a where= clause selects from it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_LAYER_TABLE_HPP
#define SBRT_LAYER_TABLE_HPP

#include <string>
#include <vector>

extern "C" {
#include <grass/dbmi.h>
#include <grass/vector.h>
}

namespace sbrt_grass {

/// \brief A database driver open on a layer's table, shut down on scope
/// exit. A layer without a table, or a database that does not open,
/// throws sbrt::Error (the view server answers it and goes on).
class LayerTable {
public:
    /// `option`: what needs the table, for the message ("where=").
    LayerTable(Map_info &map, int layer, const char *option);
    ~LayerTable();
    LayerTable(const LayerTable &) = delete;
    LayerTable &operator=(const LayerTable &) = delete;
    dbDriver *driver() { return driver_; }
    const field_info &info() const { return *info_; }

private:
    field_info *info_ = nullptr;
    dbDriver *driver_ = nullptr;
};

/// The sorted categories of the table's rows that the SQL clause `where`
/// selects (as v.what.rast's where=); a failing query throws sbrt::Error.
std::vector<int> selected_categories(LayerTable &table, const std::string &where);

} // namespace sbrt_grass

#endif
