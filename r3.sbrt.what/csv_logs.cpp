/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=csv: a row per layer of each point (gaps left out:
 *            bottom and top of neighbouring layers show them) and per
 *            voxel, with json's key names; RFC 4180 whatever the model
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
    // with channels: "level" and one column per channel, empty on layer rows
    std::string channel_header, no_values;
    if (!source.channels.empty()) {
        channel_header = ",level";
        no_values = ",";
        for (const sbrt::ChannelInfo &c : source.channels) {
            channel_header += "," + csv_field(c.name);
            no_values += ",";
        }
    }
    std::fprintf(out, "point,x,y,cat,status,row,col,class,label,top,bottom,thickness%s\n",
                 channel_header.c_str());
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
        if (!p.log || p.log->is_empty()) {
            std::fprintf(out, "%s,,,,,%s\n", head.c_str(), no_values.c_str());
            continue;
        }
        for (const sbrt::LogEntry &e : p.log->entries) {
            if (e.is_gap())
                continue;
            const sbrt::Material &m = material_of(model, e.material);
            std::fprintf(out, "%s,%d,%s,%s,%s,%s%s\n", head.c_str(), m.id,
                         csv_field(m.label).c_str(), csv_number(e.top).c_str(),
                         csv_number(e.bottom).c_str(), csv_number(e.thickness()).c_str(),
                         no_values.c_str());
        }
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
            std::fprintf(out, "%s,%s,%s,%s,%s,%s%s\n", head.c_str(), klass.c_str(),
                         label.c_str(), csv_number(v.top).c_str(),
                         csv_number(v.bottom).c_str(), csv_number(v.top - v.bottom).c_str(),
                         values.c_str());
        }
    }
}
