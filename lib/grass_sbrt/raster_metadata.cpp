/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Titles, category labels, units and history of a map cut to
 *            what GRASS 8.2 reads back
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "raster_metadata.hpp"

#include <ctime>

#include "util/safe_text.hpp"

namespace sbrt_grass {

namespace {

void fill_history(struct History *history, const MapHistory &fields)
{
    Rast_command_history(history);
    if (!fields.data_source_1.empty())
        set_history_field(history, HIST_DATSRC_1, fields.data_source_1);
    if (!fields.data_source_2.empty())
        set_history_field(history, HIST_DATSRC_2, fields.data_source_2);
    if (!fields.keywords.empty())
        set_history_field(history, HIST_KEYWRD, fields.keywords);
}

} // namespace

std::string metadata_line(std::string_view text, std::size_t max_bytes)
{
    return sbrt::fit_bytes(sbrt::printable(text), max_bytes);
}

std::string history_date()
{
    const time_t now = time(nullptr);
    char date[64];
    strftime(date, sizeof date, "%a %b %d %H:%M:%S %Y", localtime(&now));
    return date;
}

void set_history_field(struct History *history, int field, std::string_view text)
{
    Rast_set_history(history, field, metadata_line(text, MAX_HISTORY_FIELD_BYTES).c_str());
}

void write_raster_history(const char *name, const MapHistory &fields)
{
    struct History history;
    Rast_short_history(name, "raster", &history);
    fill_history(&history, fields);
    Rast_write_history(name, &history);
    Rast_free_history(&history);
}

void write_raster3d_history(const char *name, const MapHistory &fields)
{
    struct History history;
    Rast_short_history(name, "raster3d", &history);
    fill_history(&history, fields);
    if (Rast3d_write_history(name, &history) < 0)
        G_warning(_("Unable to write the history of 3D raster map <%s>"), name);
    Rast_free_history(&history);
}

void put_raster_title(const char *name, std::string_view title)
{
    const std::string line = metadata_line(title, MAX_TITLE_BYTES);
    if (Rast_put_cell_title(name, line.c_str()) < 0)
        G_warning(_("Unable to write the title of raster map <%s>"), name);
}

void write_raster_units(const char *name, std::string_view units)
{
    Rast_write_units(name, metadata_line(units, MAX_UNITS_BYTES).c_str());
}

} // namespace sbrt_grass
