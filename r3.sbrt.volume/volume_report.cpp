/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The volumes as a readable table, JSON or CSV (the formats of
 *            GRASS's newer modules)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "output_format.hpp"
#include "util/safe_text.hpp"
#include "volume.hpp"

namespace {

using Json = nlohmann::ordered_json;

/// A number for CSV: 17 significant digits; nan, inf and -inf as such.
std::string csv_number(double value)
{
    // no number (nan, +-inf): an empty field, as r3.sbrt.what writes it
    if (!std::isfinite(value))
        return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// Characters (not bytes) of valid UTF-8 `text`, for aligning columns.
size_t width_of(const std::string &text)
{
    return size_t(std::count_if(text.begin(), text.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

/// `text` padded with spaces to `width` characters.
std::string padded(const std::string &text, size_t width)
{
    const size_t w = width_of(text);
    return w >= width ? text : text + std::string(width - w, ' ');
}

/// Class ids and labels of a set, in the order of their ids.
struct SetNames {
    std::vector<int> ids;
    std::vector<std::string> labels;
};

SetNames names_of(const std::vector<sbrt::Material> &table, const sbrt::ClassSet &set)
{
    SetNames names;
    std::vector<std::pair<int, std::string>> classes;
    for (uint32_t m : set.materials())
        classes.emplace_back(table[m].id, table[m].label);
    std::sort(classes.begin(), classes.end());
    for (const auto &[id, label] : classes) {
        names.ids.push_back(id);
        names.labels.push_back(label);
    }
    return names;
}

void write_plain(FILE *out, const VolumeReport &r, const sbrt::VolumeTable &table)
{
    const bool areas = !r.categories.empty();
    // the rows' cells as text, for the widths of the columns
    struct Row {
        std::string area, classes;
        double volume;
        unsigned long long cells;
    };
    std::vector<Row> rows;
    for (int z = 0; z < table.zones(); ++z) {
        const std::string area = areas ? std::to_string(r.categories[size_t(z)]) : "";
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            rows.push_back({area, sbrt::printable(r.sets[s].describe(*r.materials)), v.volume,
                            (unsigned long long)v.cells});
        }
        if (!r.probability.empty()) {
            const sbrt::ExpectedVolume &e = r.expected[size_t(z)];
            rows.push_back({area, sbrt::printable("expected: " + r.probability), e.volume,
                            (unsigned long long)e.cells});
        }
    }
    size_t area_width = 8, classes_width = 40;
    for (const Row &row : rows) {
        area_width = std::max(area_width, width_of(row.area));
        classes_width = std::max(classes_width, width_of(row.classes));
    }
    const std::string volume = "volume (cubic " + sbrt::printable(r.units) + ")";
    if (areas)
        std::fprintf(out, "%s ", padded("area", area_width).c_str());
    std::fprintf(out, "%s %24s %10s\n", padded("classes", classes_width).c_str(),
                 volume.c_str(), "cells");
    for (const Row &row : rows) {
        if (areas)
            std::fprintf(out, "%s ", padded(row.area, area_width).c_str());
        std::fprintf(out, "%s %24.3f %10llu\n", padded(row.classes, classes_width).c_str(),
                     row.volume, row.cells);
    }
}

/// A row of "volumes" or "expected", begun: its area, where there are areas.
Json json_row(const VolumeReport &r, int zone)
{
    Json row = Json::object();
    if (!r.categories.empty())
        row["area"] = r.categories[size_t(zone)];
    return row;
}

void write_json(FILE *out, const VolumeReport &r, const sbrt::VolumeTable &table)
{
    Json report = Json::object();
    report["input"] = r.input;
    report["units"] = r.units;
    Json volumes = Json::array();
    for (int z = 0; z < table.zones(); ++z)
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            const SetNames names = names_of(*r.materials, r.sets[s]);
            Json row = json_row(r, z);
            row["classes"] = names.ids;
            row["labels"] = names.labels;
            row["volume"] = v.volume;
            row["cells"] = v.cells;
            volumes.push_back(std::move(row));
        }
    report["volumes"] = std::move(volumes);
    if (!r.probability.empty()) {
        report["probability"] = r.probability;
        Json expected = Json::array();
        for (size_t z = 0; z < r.expected.size(); ++z) {
            Json row = json_row(r, int(z));
            row["volume"] = r.expected[z].volume;
            row["cells"] = r.expected[z].cells;
            expected.push_back(std::move(row));
        }
        report["expected"] = std::move(expected);
    }
    // labels come from the model's file: bytes that are not UTF-8 become
    // U+FFFD, control characters are escaped, nan and inf become null
    std::fprintf(out, "%s\n", sbrt_grass::json_text(report).c_str());
}

void write_csv(FILE *out, const VolumeReport &r, const sbrt::VolumeTable &table,
               char separator)
{
    const bool areas = !r.categories.empty();
    const bool expected = !r.probability.empty();
    // a record with the area's category first where there are areas
    const auto write = [&](int zone, std::vector<std::string> fields) {
        if (areas)
            fields.insert(fields.begin(),
                          zone < 0 ? std::string("area")
                                   : std::to_string(r.categories[size_t(zone)]));
        std::fputs(sbrt_grass::csv_record(fields, separator).c_str(), out);
    };
    std::vector<std::string> header = {"classes", "labels", "volume", "cells"};
    if (expected)
        header.push_back("probability");
    write(-1, header);
    for (int z = 0; z < table.zones(); ++z)
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            const SetNames names = names_of(*r.materials, r.sets[s]);
            std::string ids, labels;
            for (size_t i = 0; i < names.ids.size(); ++i) {
                ids += (i ? " " : "") + std::to_string(names.ids[i]);
                labels += (i ? ";" : "") + names.labels[i];
            }
            std::vector<std::string> row = {ids, labels, csv_number(v.volume),
                                            std::to_string(v.cells)};
            if (expected)
                row.emplace_back();
            write(z, row);
            if (s + 1 == table.sets() && expected)
                // the zone's expected volume: no classes, the probability named
                write(z, {"", "", csv_number(r.expected[size_t(z)].volume),
                          std::to_string(r.expected[size_t(z)].cells), r.probability});
        }
}

} // namespace

void write_report(FILE *out, sbrt_grass::OutputFormat format, char separator,
                  const VolumeReport &report, const sbrt::VolumeTable &table)
{
    switch (format) {
    case sbrt_grass::OutputFormat::json:
        write_json(out, report, table);
        break;
    case sbrt_grass::OutputFormat::csv:
        write_csv(out, report, table, separator);
        break;
    default:
        write_plain(out, report, table);
        break;
    }
}
