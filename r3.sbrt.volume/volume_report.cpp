/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * PURPOSE:   The volumes as a readable table, JSON or CSV (the formats of
 *            GRASS's newer modules)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <string>

#include "volume.hpp"

namespace {

std::string json_string(const std::string &s)
{
    std::string out = "\"";
    for (const char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += ch;
        }
        else if (c < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        }
        else {
            out += ch;
        }
    }
    return out + "\"";
}

std::string csv_field(const std::string &s)
{
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string out = "\"";
    for (const char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

/// Class ids and labels of a set, in the order of their ids.
struct SetNames {
    std::vector<int> ids;
    std::vector<std::string> labels;
};

SetNames names_of(const sbrt::Model &model, const sbrt::ClassSet &set)
{
    SetNames names;
    std::vector<std::pair<int, std::string>> classes;
    for (uint32_t m : set.materials())
        classes.emplace_back(model.materials()[m].id, model.materials()[m].label);
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
    const std::string volume = "volume (cubic " + r.units + ")";
    if (areas)
        std::fprintf(out, "%-8s ", "area");
    std::fprintf(out, "%-40s %24s %10s\n", "classes", volume.c_str(), "cells");
    for (int z = 0; z < table.zones(); ++z)
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            if (areas)
                std::fprintf(out, "%-8d ", r.categories[size_t(z)]);
            std::fprintf(out, "%-40s %24.3f %10llu\n", r.sets[s].describe(*r.model).c_str(),
                         v.volume, (unsigned long long)v.cells);
            if (s + 1 == table.sets() && !r.probability.empty()) {
                const sbrt::ExpectedVolume &e = r.expected[size_t(z)];
                if (areas)
                    std::fprintf(out, "%-8d ", r.categories[size_t(z)]);
                std::fprintf(out, "%-40s %24.3f %10llu\n",
                             ("expected: " + r.probability).c_str(), e.volume,
                             (unsigned long long)e.cells);
            }
        }
}

void write_json(FILE *out, const VolumeReport &r, const sbrt::VolumeTable &table)
{
    std::fprintf(out, "{\n  \"input\": %s,\n  \"units\": %s,\n  \"volumes\": [",
                 json_string(r.input).c_str(), json_string(r.units).c_str());
    const char *separator = "\n";
    for (int z = 0; z < table.zones(); ++z)
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            const SetNames names = names_of(*r.model, r.sets[s]);
            std::string ids, labels;
            for (size_t i = 0; i < names.ids.size(); ++i) {
                ids += (i ? ", " : "") + std::to_string(names.ids[i]);
                labels += (i ? ", " : "") + json_string(names.labels[i]);
            }
            std::fprintf(out, "%s    {", separator);
            if (!r.categories.empty())
                std::fprintf(out, "\"area\": %d, ", r.categories[size_t(z)]);
            std::fprintf(out,
                         "\"classes\": [%s], \"labels\": [%s], \"volume\": %.17g, "
                         "\"cells\": %llu}",
                         ids.c_str(), labels.c_str(), v.volume, (unsigned long long)v.cells);
            separator = ",\n";
        }
    std::fprintf(out, "\n  ]");
    if (!r.probability.empty()) {
        std::fprintf(out, ",\n  \"probability\": %s,\n  \"expected\": [",
                     json_string(r.probability).c_str());
        for (size_t z = 0; z < r.expected.size(); ++z) {
            std::fprintf(out, "%s\n    {", z ? "," : "");
            if (!r.categories.empty())
                std::fprintf(out, "\"area\": %d, ", r.categories[z]);
            std::fprintf(out, "\"volume\": %.17g, \"cells\": %llu}", r.expected[z].volume,
                         (unsigned long long)r.expected[z].cells);
        }
        std::fprintf(out, "\n  ]");
    }
    std::fprintf(out, "\n}\n");
}

void write_csv(FILE *out, const VolumeReport &r, const sbrt::VolumeTable &table)
{
    const bool areas = !r.categories.empty();
    const bool expected = !r.probability.empty();
    std::fprintf(out, "%sclasses,labels,volume,cells%s\n", areas ? "area," : "",
                 expected ? ",probability" : "");
    for (int z = 0; z < table.zones(); ++z)
        for (size_t s = 0; s < table.sets(); ++s) {
            const sbrt::Volume &v = table.at(z, s);
            const SetNames names = names_of(*r.model, r.sets[s]);
            std::string ids, labels;
            for (size_t i = 0; i < names.ids.size(); ++i) {
                ids += (i ? " " : "") + std::to_string(names.ids[i]);
                labels += (i ? ";" : "") + names.labels[i];
            }
            if (areas)
                std::fprintf(out, "%d,", r.categories[size_t(z)]);
            std::fprintf(out, "%s,%s,%.17g,%llu%s\n", ids.c_str(), csv_field(labels).c_str(),
                         v.volume, (unsigned long long)v.cells, expected ? "," : "");
            if (s + 1 == table.sets() && expected) {
                // the zone's expected volume: no classes, the probability named
                if (areas)
                    std::fprintf(out, "%d,", r.categories[size_t(z)]);
                std::fprintf(out, ",,%.17g,%llu,%s\n", r.expected[size_t(z)].volume,
                             (unsigned long long)r.expected[size_t(z)].cells,
                             csv_field(r.probability).c_str());
            }
        }
}

} // namespace

void write_report(FILE *out, ReportFormat format, const VolumeReport &report,
                  const sbrt::VolumeTable &table)
{
    switch (format) {
    case ReportFormat::plain:
        write_plain(out, report, table);
        break;
    case ReportFormat::json:
        write_json(out, report, table);
        break;
    case ReportFormat::csv:
        write_csv(out, report, table);
        break;
    }
}
