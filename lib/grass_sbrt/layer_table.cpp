/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   The attribute table of a vector map's layer, and where=
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "layer_table.hpp"

#include <algorithm>

#include "grass.hpp"
#include "util/error.hpp"

namespace sbrt_grass {

namespace {

/// A value of a request as a message quotes it: it can be megabytes.
std::string quoted(const std::string &text)
{
    constexpr size_t limit = 200;
    return text.size() <= limit ? text : text.substr(0, limit) + "...";
}

} // namespace

LayerTable::LayerTable(Map_info &map, int layer, const char *option)
{
    info_ = Vect_get_field(&map, layer);
    if (!info_)
        sbrt::fail(option, ": ", _("vector map"), " <", Vect_get_full_name(&map), "> ",
                   _("has no attribute table in layer"), " ", layer, " (",
                   _("connect one with v.db.connect, or choose layer="), ")");
    driver_ = db_start_driver_open_database(info_->driver, Vect_subst_var(info_->database, &map));
    if (!driver_)
        sbrt::fail(_("Unable to open database"), " <", info_->database, "> ", _("by driver"),
                   " <", info_->driver, ">");
}

LayerTable::~LayerTable()
{
    if (driver_)
        db_close_database_shutdown_driver(driver_);
    G_free(info_); // its strings live as long as the module, as in GRASS's own modules
}

std::vector<int> selected_categories(LayerTable &table, const std::string &where)
{
    int *cats = nullptr;
    const int n = db_select_int(table.driver(), table.info().table, table.info().key,
                                where.c_str(), &cats);
    if (n < 0)
        sbrt::fail("where=", quoted(where), ": ", _("the query failed on table"), " <",
                   table.info().table, ">");
    std::vector<int> selected(cats, cats + n);
    G_free(cats);
    std::sort(selected.begin(), selected.end());
    return selected;
}

} // namespace sbrt_grass
