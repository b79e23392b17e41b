/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=json and format=csv: the layers of each point (gaps
 *            left out: bottom and top of neighbouring layers show them),
 *            with the same key names in both
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "log_writers.hpp"

namespace {

/// `text` as a json string, quotes included (RFC 8259: quote, backslash
/// and control characters escaped; other bytes as they are, UTF-8).
std::string json_string(const std::string &text)
{
    std::string out = "\"";
    for (const unsigned char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += char(c);
        }
        else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        }
        else {
            out += char(c);
        }
    }
    return out + "\"";
}

/// `text` as a csv field (RFC 4180): quoted, quotes doubled, where it
/// holds a comma, a quote or a line break.
std::string csv_field(const std::string &text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos)
        return text;
    std::string out = "\"";
    for (const char c : text)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

/// The point's fields before its intervals: "point", "x", "y", "cat",
/// "status", "row", "col" (json: null where there is none).
void write_json_point(FILE *out, size_t index, const PointLog &p)
{
    std::fprintf(out, "  {\n    \"point\": %zu,\n    \"x\": %s,\n    \"y\": %s,\n", index + 1,
                 number_text(p.point.x).c_str(), number_text(p.point.y).c_str());
    if (p.point.cat >= 0)
        std::fprintf(out, "    \"cat\": %d,\n", p.point.cat);
    else
        std::fprintf(out, "    \"cat\": null,\n");
    std::fprintf(out, "    \"status\": \"%s\",\n", point_status(p));
    if (p.log)
        std::fprintf(out, "    \"row\": %d,\n    \"col\": %d,\n", p.log->cell.row,
                     p.log->cell.col);
    else
        std::fprintf(out, "    \"row\": null,\n    \"col\": null,\n");
}

/// ",\n    "voxels": [...]": each voxel of the point's span, top down,
/// with its class (null in a cave) and every channel's value.
void write_json_voxels(FILE *out, const LogSource &source, const PointLog &p)
{
    std::fprintf(out, ",\n    \"voxels\": [");
    for (size_t v = 0; v < p.voxels.size(); ++v) {
        const sbrt::VoxelValues &voxel = p.voxels[v];
        std::fprintf(out, "%s\n      {\"level\": %u, \"top\": %s, \"bottom\": %s, ",
                     v ? "," : "", voxel.level, number_text(voxel.top).c_str(),
                     number_text(voxel.bottom).c_str());
        if (voxel.material == sbrt::EMPTY)
            std::fprintf(out, "\"class\": null, \"values\": {");
        else
            std::fprintf(out, "\"class\": %d, \"values\": {",
                         material_of(source.model, voxel.material).id);
        for (size_t c = 0; c < voxel.values.size(); ++c)
            std::fprintf(out, "%s%s: %s", c ? ", " : "",
                         json_string(source.channels[c].name).c_str(),
                         value_text(voxel.values[c], "null").c_str());
        std::fprintf(out, "}}");
    }
    std::fprintf(out, "%s]", p.voxels.empty() ? "" : "\n    ");
}

} // namespace

void write_json_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs)
{
    const sbrt::Model &model = source.model;
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < logs.size(); ++i) {
        const PointLog &p = logs[i];
        write_json_point(out, i, p);
        std::fprintf(out, "    \"intervals\": [");
        bool first = true;
        if (p.log)
            for (const sbrt::LogEntry &e : p.log->entries) {
                if (e.is_gap())
                    continue;
                const sbrt::Material &m = material_of(model, e.material);
                std::fprintf(out,
                             "%s\n      {\"class\": %d, \"label\": %s, \"top\": %s, "
                             "\"bottom\": %s, \"thickness\": %s}",
                             first ? "" : ",", m.id, json_string(m.label).c_str(),
                             number_text(e.top).c_str(), number_text(e.bottom).c_str(),
                             number_text(e.thickness()).c_str());
                first = false;
            }
        std::fprintf(out, "%s]", first ? "" : "\n    ");
        if (!source.channels.empty())
            write_json_voxels(out, source, p);
        std::fprintf(out, "\n  }%s\n", i + 1 < logs.size() ? "," : "");
    }
    std::fprintf(out, "]\n");
}

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
        std::string head = std::to_string(i + 1) + "," + number_text(p.point.x) + "," +
                           number_text(p.point.y) + "," +
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
                         csv_field(m.label).c_str(), number_text(e.top).c_str(),
                         number_text(e.bottom).c_str(), number_text(e.thickness()).c_str(),
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
                values += "," + value_text(value, "");
            std::fprintf(out, "%s,%s,%s,%s,%s,%s%s\n", head.c_str(), klass.c_str(),
                         label.c_str(), number_text(v.top).c_str(),
                         number_text(v.bottom).c_str(), number_text(v.top - v.bottom).c_str(),
                         values.c_str());
        }
    }
}
