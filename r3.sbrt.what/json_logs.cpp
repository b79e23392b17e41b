/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=json: the layers of each point (gaps left out: bottom
 *            and top of neighbouring layers show them) and its voxels,
 *            written through nlohmann::json so that the output is valid
 *            JSON (RFC 8259) and valid UTF-8 whatever the model holds:
 *            labels of another mapset with control characters or bytes
 *            that are no UTF-8, channel values of +-inf
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cmath>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "log_writers.hpp"
#include "output_format.hpp"
#include "util/safe_text.hpp"

namespace {

/// Keys in the order they are set (point, x, y, ... as the manual lists them).
using Json = nlohmann::ordered_json;

/// A number as json gives it: null where it is none (nan, +-inf, which
/// RFC 8259 has no form for), else the value of its 15 significant
/// digits (number_text), an integer where it is one: 584, 2.4, not
/// 584.0 or 2.4000000000000004.
Json json_number(double value)
{
    if (!std::isfinite(value))
        return nullptr;
    const double rounded = std::strtod(number_text(value).c_str(), nullptr);
    if (std::fabs(rounded) < 9007199254740992.0 && rounded == std::trunc(rounded))
        return static_cast<std::int64_t>(rounded);
    return rounded;
}

/// A text of the model (label, channel name) as a json string: valid
/// UTF-8 (the dump escapes control characters, escape_controls the rest).
Json json_text(const std::string &text)
{
    return sbrt::valid_utf8(text);
}

/// `value` written by the library on one line, ", " and ": " between
/// items as the manual shows them; a byte that is no UTF-8 (none is left
/// after json_text) would become U+FFFD, never be written raw; no
/// control character left unescaped.
std::string one_line(const Json &value)
{
    const auto dump = [](const Json &v) { return sbrt_grass::json_text(v, -1); };
    if (value.is_object() && !value.empty()) {
        std::string text = "{";
        for (auto item = value.begin(); item != value.end(); ++item)
            text += (item == value.begin() ? "" : ", ") + dump(Json(item.key())) + ": " +
                    one_line(item.value());
        return text + "}";
    }
    if (value.is_array() && !value.empty()) {
        std::string text = "[";
        for (size_t i = 0; i < value.size(); ++i)
            text += (i ? ", " : "") + one_line(value[i]);
        return text + "]";
    }
    return dump(value);
}

/// A point's object: a key per line, a list's items one per line.
std::string point_text(const Json &point)
{
    std::string text = "  {";
    for (auto item = point.begin(); item != point.end(); ++item) {
        text += std::string(item == point.begin() ? "" : ",") + "\n    " +
                one_line(Json(item.key())) + ": ";
        const Json &value = item.value();
        if (!value.is_array() || value.empty()) {
            text += one_line(value);
            continue;
        }
        text += "[";
        for (size_t i = 0; i < value.size(); ++i)
            text += std::string(i ? "," : "") + "\n      " + one_line(value[i]);
        text += "\n    ]";
    }
    return text + "\n  }";
}

/// The layers of a point's column (gaps left out), top down, with the
/// depths of their tops and bottoms below the surface.
Json json_intervals(const sbrt::Model &model, const PointLog &p)
{
    Json intervals = Json::array();
    if (p.log)
        for (const sbrt::LogEntry &e : p.log->entries) {
            if (e.is_gap())
                continue;
            const sbrt::Material &m = material_of(model, e.material);
            intervals.push_back({{"class", m.id},
                                 {"label", json_text(m.label)},
                                 {"top", json_number(e.top)},
                                 {"bottom", json_number(e.bottom)},
                                 {"thickness", json_number(e.thickness())},
                                 {"top_depth", json_number(*surface_of(p) - e.top)},
                                 {"bottom_depth", json_number(*surface_of(p) - e.bottom)}});
        }
    return intervals;
}

/// Each voxel of the point's span, top down, with its class (null in a
/// cave) and every channel's value (null for none).
Json json_voxels(const LogSource &source, const PointLog &p)
{
    Json voxels = Json::array();
    const std::optional<double> surface = surface_of(p);
    const auto depth = [&](double height) {
        return surface ? json_number(*surface - height) : Json(nullptr);
    };
    for (const sbrt::VoxelValues &v : p.voxels) {
        Json values = Json::object();
        for (size_t c = 0; c < v.values.size(); ++c)
            values[sbrt::valid_utf8(source.channels[c].name)] = json_number(v.values[c]);
        voxels.push_back(
            {{"level", v.level},
             {"top", json_number(v.top)},
             {"bottom", json_number(v.bottom)},
             {"top_depth", depth(v.top)},
             {"bottom_depth", depth(v.bottom)},
             {"class", v.material == sbrt::EMPTY
                           ? Json(nullptr)
                           : Json(material_of(source.model, v.material).id)},
             {"values", values}});
    }
    return voxels;
}

/// A point with its fields, its intervals and, with channels, its voxels
/// (null where there is none: cat of coordinates=, row and col outside).
Json json_point(const LogSource &source, size_t index, const PointLog &p)
{
    Json point;
    point["point"] = index + 1;
    point["x"] = json_number(p.point.x);
    point["y"] = json_number(p.point.y);
    point["cat"] = p.point.cat >= 0 ? Json(p.point.cat) : Json(nullptr);
    point["status"] = point_status(p);
    point["row"] = p.log ? Json(p.log->cell.row) : Json(nullptr);
    point["col"] = p.log ? Json(p.log->cell.col) : Json(nullptr);
    // the heights' unit and datum (null where the model has none) and the
    // surface the depths are measured from (null without layers)
    point["elevation_unit"] = source.elevation_unit;
    point["vertical_datum"] =
        vertical_datum(source).empty() ? Json(nullptr) : json_text(vertical_datum(source));
    const std::optional<double> surface = surface_of(p);
    point["surface"] = surface ? json_number(*surface) : Json(nullptr);
    point["intervals"] = json_intervals(source.model, p);
    if (!source.channels.empty())
        point["voxels"] = json_voxels(source, p);
    return point;
}

} // namespace

void write_json_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs)
{
    // a point at a time: thousands of points with channels need no tree
    // of them all
    std::fputs("[\n", out);
    for (size_t i = 0; i < logs.size(); ++i) {
        const std::string text = point_text(json_point(source, i, logs[i]));
        std::fputs(text.c_str(), out);
        std::fputs(i + 1 < logs.size() ? ",\n" : "\n", out);
    }
    std::fputs("]\n", out);
}
