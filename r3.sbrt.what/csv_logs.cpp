/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=csv: a row per layer of each point (gaps left out:
 *            bottom and top of neighbouring layers show them) and, with
 *            -v, per voxel (column kind), with json's key names; RFC 4180 whatever the model
 *            holds (labels of another mapset with separators, quotes,
 *            control characters or bytes that are no UTF-8; values of inf)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "log_writers.hpp"
#include "util/safe_text.hpp"

namespace {

using sbrt::csv_field;

/// A number as a csv field: empty where it is none (nan, +-inf).
std::string csv_number(double value)
{
    return value_text(value, "");
}

} // namespace

void write_csv_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs)
{
    const sbrt::Model &model = source.model;
    // with voxel rows: "kind" (layer or voxel); with channels besides,
    // "level" and one column per channel, empty on layer rows
    const bool voxels = source.voxel_rows;
    std::string extra_header, no_values;
    if (voxels && !source.channels.empty()) {
        extra_header = ",level";
        no_values = ",";
        for (const sbrt::ChannelInfo &c : source.channels) {
            extra_header += "," + csv_field(c.name);
            no_values += ",";
        }
    }
    std::fprintf(out,
                 "point,x,y,cat,status,row,col,class,label,top,bottom,thickness,"
                 "top_depth,bottom_depth,elevation_unit,vertical_datum%s%s\n",
                 voxels ? ",kind" : "", extra_header.c_str());
    // on each row: the heights' unit and datum (another mapset's text)
    const std::string reference = "," + csv_field(source.elevation_unit) + "," +
                                  csv_field(vertical_datum(source));
    const std::string layer_kind = voxels ? ",layer" : "";
    for (size_t i = 0; i < logs.size(); ++i) {
        const PointLog &p = logs[i];
        // the point's fields, repeated on each of its rows
        std::string head = std::to_string(i + 1) + "," + csv_number(p.point.x) + "," +
                           csv_number(p.point.y) + "," +
                           (p.point.cat >= 0 ? std::to_string(p.point.cat) : "") + "," +
                           point_status(p) + ",";
        if (p.log)
            head += std::to_string(p.log->cell.row) + "," + std::to_string(p.log->cell.col);
        else
            head += ",";
        const std::optional<double> surface = surface_of(p);
        if (!surface) {
            std::fprintf(out, "%s,,,,,,,%s%s%s\n", head.c_str(), reference.c_str(),
                         layer_kind.c_str(), no_values.c_str());
            continue;
        }
        for (const sbrt::LogEntry &e : p.log->entries) {
            if (e.is_gap())
                continue;
            const sbrt::Material &m = material_of(model, e.material);
            std::fprintf(out, "%s,%d,%s,%s,%s,%s,%s,%s%s%s%s\n", head.c_str(), m.id,
                         csv_field(m.label).c_str(), csv_number(e.top).c_str(),
                         csv_number(e.bottom).c_str(), csv_number(e.thickness()).c_str(),
                         csv_number(*surface - e.top).c_str(),
                         csv_number(*surface - e.bottom).c_str(), reference.c_str(),
                         layer_kind.c_str(), no_values.c_str());
        }
        if (!voxels)
            continue;
        for (const sbrt::VoxelValues &v : p.voxels) {
            std::string klass, label;
            if (v.material != sbrt::EMPTY) {
                const sbrt::Material &m = material_of(model, v.material);
                klass = std::to_string(m.id);
                label = csv_field(m.label);
            }
            std::string values = "," + std::to_string(v.level);
            for (const double value : v.values)
                values += "," + csv_number(value);
            std::fprintf(out, "%s,%s,%s,%s,%s,%s,%s,%s%s,voxel%s\n", head.c_str(),
                         klass.c_str(), label.c_str(), csv_number(v.top).c_str(),
                         csv_number(v.bottom).c_str(), csv_number(v.top - v.bottom).c_str(),
                         csv_number(*surface - v.top).c_str(),
                         csv_number(*surface - v.bottom).c_str(), reference.c_str(),
                         values.c_str());
        }
    }
}
