/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=csv: a row per layer of each point (gaps left out:
 *            bottom and top of neighbouring layers show them) and, with
 *            -v, per voxel (column kind), with json's key names; RFC 4180
 *            with the separator of separator= whatever the model holds
 *            (labels of another mapset with separators, quotes, control
 *            characters or bytes that are no UTF-8; values of inf)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "log_writers.hpp"
#include "output_format.hpp"

namespace {

using Fields = std::vector<std::string>;

/// A number as a csv field: empty where it is none (nan, +-inf).
std::string csv_number(double value)
{
    return value_text(value, "");
}

/// `fields` and then `more`.
Fields joined(Fields fields, const Fields &more)
{
    fields.insert(fields.end(), more.begin(), more.end());
    return fields;
}

} // namespace

void write_csv_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs)
{
    const sbrt::Model &model = source.model;
    const auto write = [&](const Fields &fields) {
        std::fputs(sbrt_grass::csv_record(fields, source.separator).c_str(), out);
    };
    // with voxel rows: "kind" (layer or voxel); with channels besides,
    // "level" and one column per channel, empty on layer rows
    const bool voxels = source.voxel_rows;
    Fields header = {"point", "x", "y", "cat", "status", "row", "col", "class", "label",
                     "top", "bottom", "thickness", "top_depth", "bottom_depth",
                     "elevation_unit", "vertical_datum"};
    Fields layer_tail;
    if (voxels) {
        header.push_back("kind");
        layer_tail.push_back("layer");
        if (!source.channels.empty()) {
            header.push_back("level");
            layer_tail.emplace_back();
            for (const sbrt::ChannelInfo &c : source.channels) {
                header.push_back(c.name);
                layer_tail.emplace_back();
            }
        }
    }
    write(header);
    // on each row: the heights' unit and datum (another mapset's text)
    const Fields reference = {source.elevation_unit, vertical_datum(source)};
    for (size_t i = 0; i < logs.size(); ++i) {
        const PointLog &p = logs[i];
        // the point's fields, repeated on each of its rows
        const Fields head = {std::to_string(i + 1),
                             csv_number(p.point.x),
                             csv_number(p.point.y),
                             p.point.cat >= 0 ? std::to_string(p.point.cat) : "",
                             point_status(p),
                             p.log ? std::to_string(p.log->cell.row) : "",
                             p.log ? std::to_string(p.log->cell.col) : ""};
        const std::optional<double> surface = surface_of(p);
        if (!surface) {
            write(joined(joined(joined(head, Fields(7)), reference), layer_tail));
            continue;
        }
        for (const sbrt::LogEntry &e : p.log->entries) {
            if (e.is_gap())
                continue;
            const sbrt::Material &m = material_of(model, e.material);
            const Fields layer = {std::to_string(m.id),
                                  m.label,
                                  csv_number(e.top),
                                  csv_number(e.bottom),
                                  csv_number(e.thickness()),
                                  csv_number(*surface - e.top),
                                  csv_number(*surface - e.bottom)};
            write(joined(joined(joined(head, layer), reference), layer_tail));
        }
        if (!voxels)
            continue;
        for (const sbrt::VoxelValues &v : p.voxels) {
            std::string klass, label;
            if (v.material != sbrt::EMPTY) {
                const sbrt::Material &m = material_of(model, v.material);
                klass = std::to_string(m.id);
                label = m.label;
            }
            const Fields voxel = {klass,
                                  label,
                                  csv_number(v.top),
                                  csv_number(v.bottom),
                                  csv_number(v.top - v.bottom),
                                  csv_number(*surface - v.top),
                                  csv_number(*surface - v.bottom)};
            Fields tail = {"voxel"};
            if (!source.channels.empty()) {
                tail.push_back(std::to_string(v.level));
                for (const double value : v.values)
                    tail.push_back(csv_number(value));
            }
            write(joined(joined(joined(head, voxel), reference), tail));
        }
    }
}
