/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   format=json of -p (the SBRT's metadata, classes, Table 1
 *            figures and property channels), of -p file= (the file's
 *            variables) and of -l (the SBRTs of the search path), written
 *            by nlohmann::json: valid JSON and UTF-8 whatever a file's
 *            attributes or a model's labels hold
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "report.hpp"

#include "convert.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "file_variable.hpp"
#include "grass.hpp"
#include "model/material_table.hpp"
#include "output_format.hpp"
#include "sbrt_manage.hpp"

namespace {

using Json = nlohmann::ordered_json;

void print_json(const Json &value)
{
    std::fprintf(stdout, "%s\n", sbrt_grass::json_text(value).c_str());
}

/// The classes by id, with the colours a render draws.
Json classes_json(const std::vector<sbrt::Material> &materials)
{
    std::vector<uint32_t> order;
    for (uint32_t i = 1; i < materials.size(); ++i)
        order.push_back(i);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return materials[a].id < materials[b].id;
    });
    Json classes = Json::array();
    for (const uint32_t i : order) {
        const sbrt::Material &m = materials[i];
        const auto rgb = sbrt::material_color(materials, i);
        classes.push_back({{"class", m.id},
                           {"label", m.label},
                           {"color", {int(rgb[0]), int(rgb[1]), int(rgb[2])}}});
    }
    return classes;
}

/// The property channels with -g's fields, as numbers where they are.
Json channels_json(const sbrt::PropertyChannels &channels)
{
    Json list = Json::array();
    for (const sbrt::ChannelInfo &c : channels.infos())
        list.push_back({{"name", c.name},
                        {"type", sbrt::channel_type_name(c.type())},
                        {"min", c.min},
                        {"max", c.max},
                        {"voxels", c.voxels},
                        {"valid", c.valid},
                        {"fill", c.has_fill ? Json(c.fill) : Json(nullptr)},
                        {"scale", c.scale},
                        {"offset", c.offset},
                        {"bytes", c.bytes},
                        {"bytes_per_voxel", c.voxels ? double(c.bytes) / double(c.voxels) : 0.0},
                        {"unit", c.unit},
                        {"kind", sbrt::channel_kind_name(c.known_kind())},
                        {"long_name", c.long_name}});
    return list;
}

} // namespace

void print_report_json(const char *name, const sbrt::Model &model,
                       const sbrt::StacksFileInfo &file,
                       const sbrt::PropertyChannels *channels)
{
    print_description_json(name, description_of(model), file, channels);
}

void print_description_json(const char *name, const ModelDescription &model,
                            const sbrt::StacksFileInfo &file,
                            const sbrt::PropertyChannels *channels)
{
    const sbrt::Frame &f = model.frame;
    const sbrt::Stats &s = model.stats;
    Json r;
    // the keys of -g, in its order
    r["name"] = name;
    r["north"] = f.north;
    r["south"] = f.south;
    r["east"] = f.east;
    r["west"] = f.west;
    r["top"] = f.top;
    r["bottom"] = f.bottom;
    r["rows"] = f.rows;
    r["cols"] = f.cols;
    r["depths"] = f.depths;
    r["nsres"] = f.ns_res();
    r["ewres"] = f.ew_res();
    r["tbres"] = f.tb_res();
    r["materials"] = model.materials.size() - 1;
    r["voxels"] = s.voxels;
    r["voxel_bytes"] = s.voxel_bytes;
    r["sbrt_bytes"] = s.sbrt_bytes;
    r["intervals"] = s.intervals;
    r["solid_intervals"] = s.solid_intervals;
    r["max_stack"] = s.max_stack;
    r["mean_stack"] = s.mean_stack;
    r["compression"] = s.compression_percent;
    r["memory_bytes_per_interval"] =
        s.intervals ? double(s.interval_bytes) / double(s.intervals) : 0.0;
    r["memory_index_bytes_per_cell"] = double(s.index_bytes) / double(f.cells());
    r["format"] = std::to_string(file.major) + "." + std::to_string(file.minor);
    r["file_bytes"] = file.bytes;
    r["file_bytes_per_interval"] = s.intervals ? double(file.bytes) / double(s.intervals) : 0.0;
    r["file_compression"] =
        s.voxel_bytes ? 100.0 * (1.0 - double(file.bytes) / double(s.voxel_bytes)) : 0.0;
    r["vertical_datum"] =
        model.vertical_datum.empty() ? Json(nullptr) : Json(model.vertical_datum);
    // and what only -p shows: the classes with their labels and colours
    r["classes"] = classes_json(model.materials);
    r["channels"] = channels ? channels_json(*channels) : Json::array();
    print_json(r);
}

void print_file_variables_json(const char *file)
{
    Json list = Json::array();
    for (const VariableSummary &v : list_file_variables(file))
        list.push_back({{"name", v.name},
                        {"type", v.type},
                        {"dimensions", v.dimensions},
                        {"sizes", v.sizes},
                        {"long_name", v.long_name},
                        {"units", v.units}});
    print_json(list);
}

void print_sbrt_list_json()
{
    Json list = Json::array();
    for (int i = 0; const char *mapset = G_get_mapset_name(i); ++i)
        for (const sbrt_grass::StoredSbrt &sbrt : sbrt_grass::list_stored_sbrts({mapset}))
            list.push_back({{"name", sbrt.name},
                            {"mapset", sbrt.mapset},
                            {"fullname", sbrt.qualified()}});
    print_json(list);
}
