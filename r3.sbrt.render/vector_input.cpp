/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Vector points, lines and attribute rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "vector_input.hpp"

#include "grass.hpp"
#include "request_error.hpp"
#include "vector_map.hpp"
extern "C" {
#include <grass/dbmi.h>
#include <grass/vector.h>
}

using sbrt_grass::LayerTable;
using sbrt_grass::VectorMap;

namespace {

/// A number from a fetched column (integer or floating point), or false
/// for NULL.
bool column_number(dbTable *table, int k, const char *name, double &out)
{
    dbColumn *column = db_get_table_column(table, k);
    dbValue *value = db_get_column_value(column);
    if (db_test_value_isnull(value))
        return false;
    switch (db_sqltype_to_Ctype(db_get_column_sqltype(column))) {
    case DB_C_TYPE_INT:
        out = db_get_value_int(value);
        return true;
    case DB_C_TYPE_DOUBLE:
        out = db_get_value_double(value);
        return true;
    default:
        bad_request(_("Column <%s> is not numeric"), name);
    }
}

/// The rows of log_top=, log_bottom=, log_class= grouped by category.
std::map<int, std::vector<LogRow>> logged_intervals(LayerTable &table,
                                                    const RenderRequest &request)
{
    std::string sql = std::string("SELECT ") + table.info().key + ", " +
                      request.log_top + ", " + request.log_bottom + ", " +
                      request.log_class + " FROM " + table.info().table;
    dbString statement;
    db_init_string(&statement);
    db_set_string(&statement, sql.c_str());
    dbCursor cursor;
    if (db_open_select_cursor(table.driver(), &statement, &cursor, DB_SEQUENTIAL) !=
        DB_OK)
        bad_request(_("Unable to read the logs (%s): check log_top=, "
                        "log_bottom= and log_class= against the columns of "
                        "table <%s>"),
                      sql.c_str(), table.info().table);
    db_free_string(&statement);
    std::map<int, std::vector<LogRow>> logs;
    dbTable *result = db_get_cursor_table(&cursor);
    const char *names[4] = {table.info().key, request.log_top.c_str(),
                            request.log_bottom.c_str(), request.log_class.c_str()};
    size_t incomplete = 0;
    for (;;) {
        int more = 0;
        if (db_fetch(&cursor, DB_NEXT, &more) != DB_OK)
            bad_request(_("Unable to fetch a row of table <%s>"), table.info().table);
        if (!more)
            break;
        double v[4];
        bool complete = true;
        for (int k = 0; k < 4; ++k)
            complete = column_number(result, k, names[k], v[k]) && complete;
        if (!complete) {
            ++incomplete;
            continue;
        }
        logs[int(v[0])].push_back({v[1], v[2], int(v[3])});
    }
    db_close_cursor(&cursor);
    if (incomplete)
        G_warning(_("%zu log rows with NULL values skipped"), incomplete);
    return logs;
}

} // namespace

BoreholeInput read_boreholes(const RenderRequest &request)
{
    // the layer's table, opened once for where= and the logs
    sbrt_grass::PointsMap map({"boreholes", request.boreholes, request.layer, request.where},
                              request.log_class.empty() ? nullptr : "log_class=");
    BoreholeInput in;
    in.is_3d = Vect_is_3d(&map.map());
    in.points = map.selected();
    if (!request.log_class.empty())
        in.logs = logged_intervals(*map.table(), request);
    return in;
}

std::vector<glm::dvec3> read_path_line(const std::string &name, bool &is_3d)
{
    VectorMap vector(name, "-1", "path_map");
    is_3d = Vect_is_3d(&vector.map());
    size_t lines = 0;
    std::vector<glm::dvec3> line;
    while (const int type = vector.next()) {
        if (!(type & GV_LINES))
            continue;
        if (lines++ == 0) {
            const line_pnts &p = vector.points();
            for (int k = 0; k < p.n_points; ++k)
                line.push_back({p.x[k], p.y[k], p.z[k]});
        }
    }
    if (line.empty())
        bad_request(_("path_map=%s has no lines: path=line needs a vector map "
                        "of lines (v.in.ascii, v.digit)"),
                      name.c_str());
    if (lines > 1)
        G_warning(_("path_map=%s has %zu lines: the camera follows the first"),
                  name.c_str(), lines);
    return line;
}

std::vector<sbrt::FencePanel> read_fence(const std::string &name)
{
    VectorMap vector(name, "-1", "fence");
    std::vector<sbrt::FencePanel> panels;
    size_t points = 0;
    while (const int type = vector.next()) {
        if (!(type & GV_LINES)) {
            points += (type & GV_POINTS) != 0;
            continue;
        }
        const line_pnts &p = vector.points();
        for (int k = 0; k + 1 < p.n_points; ++k)
            if (p.x[k] != p.x[k + 1] || p.y[k] != p.y[k + 1])
                panels.push_back({{p.x[k], p.y[k]}, {p.x[k + 1], p.y[k + 1]}});
    }
    if (panels.empty())
        bad_request(_("fence=%s has no lines (it holds %zu points): a fence "
                        "diagram needs a vector map of lines"),
                      name.c_str(), points);
    return panels;
}
