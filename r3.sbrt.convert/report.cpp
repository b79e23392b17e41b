/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   Metadata and the memory comparison of the papers' Table 1
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "report.hpp"

#include "convert.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "grass.hpp"
#include "model/material_table.hpp"
#include "util/safe_text.hpp"

namespace {

/// The property channels: type, range, fills and bytes per value on disk
/// (the compressed blocks and their table).
void print_channels(const sbrt::PropertyChannels &channels, bool shell)
{
    uint64_t all_bytes = 0, voxels = 0;
    for (const sbrt::ChannelInfo &c : channels.infos()) {
        all_bytes += c.bytes;
        voxels = std::max(voxels, c.voxels);
    }
    if (shell)
        fprintf(stdout, "channels=%zu\nchannel_bytes=%llu\nchannel_bytes_per_voxel=%.4f\n",
                channels.size(), (unsigned long long)all_bytes,
                voxels ? double(all_bytes) / double(voxels) : 0.0);
    else
        fprintf(stdout, "Property channels: %zu (%.2f MiB, %.3f bytes per voxel of the "
                        "spans for all)\n",
                channels.size(), all_bytes / (1024.0 * 1024.0),
                voxels ? double(all_bytes) / double(voxels) : 0.0);
    for (const sbrt::ChannelInfo &c : channels.infos()) {
        const double per_voxel = c.voxels ? double(c.bytes) / double(c.voxels) : 0;
        if (shell) {
            char numbers[512];
            std::snprintf(numbers, sizeof numbers,
                          "|type=%s|min=%.9g|max=%.9g|voxels=%llu|valid=%llu|fill=%s|"
                          "scale=%.17g|offset=%.17g|bytes=%llu|bytes_per_voxel=%.4f|",
                          sbrt::channel_type_name(c.type()), c.min, c.max,
                          (unsigned long long)c.voxels, (unsigned long long)c.valid,
                          c.has_fill ? std::to_string(c.fill).c_str() : "", c.scale,
                          c.offset, (unsigned long long)c.bytes, per_voxel);
            // one shell word a record: eval sets channel= (to the last one)
            // and the scalars above stay set (no pipeline of assignments)
            fprintf(stdout, "channel=%s\n",
                    sbrt::shell_word(sbrt::record_field(c.name) + numbers + "unit=" +
                                     sbrt::record_field(c.unit) + "|kind=" +
                                     sbrt::channel_kind_name(c.known_kind()) +
                                     "|long_name=" +
                                     sbrt::record_field(c.long_name))
                        .c_str());
            continue;
        }
        char fill[64] = "no fill";
        if (c.has_fill)
            std::snprintf(fill, sizeof fill, "fill %.9g", double(c.fill));
        fprintf(stdout, "  %-12s %-4s %9.6g .. %-9.6g %s, %5.1f %% valid, %.3f bytes "
                        "per voxel, %s%s%s%s%s\n",
                sbrt::printable(c.name).c_str(), sbrt::channel_type_name(c.type()), c.min,
                c.max, fill, c.voxels ? 100.0 * double(c.valid) / double(c.voxels) : 0.0,
                per_voxel, sbrt::channel_kind_name(c.known_kind()),
                c.unit.empty() ? "" : " in ", sbrt::printable(c.unit).c_str(),
                c.long_name.empty() ? "" : ": ", sbrt::printable(c.long_name).c_str());
        if (c.scale != 1 || c.offset != 0)
            fprintf(stdout, "  %-12s value = stored * %.9g + %.9g\n", "", c.scale,
                    c.offset);
    }
}

} // namespace

ModelDescription description_of(const sbrt::Model &model)
{
    return {model.frame(), model.materials(), model.vertical_datum(), model.stats()};
}

ModelDescription description_of(const sbrt::ModelSummary &summary)
{
    return {summary.frame, summary.materials, summary.vertical_datum, summary.stats};
}

void print_report(const char *name, const sbrt::Model &model,
                  const sbrt::StacksFileInfo &file, sbrt_grass::OutputFormat format,
                  const sbrt::PropertyChannels *channels)
{
    print_description(name, description_of(model), file, format, channels);
}

void print_description(const char *name, const ModelDescription &model,
                       const sbrt::StacksFileInfo &file, sbrt_grass::OutputFormat format,
                       const sbrt::PropertyChannels *channels)
{
    if (format == sbrt_grass::OutputFormat::json) {
        print_description_json(name, model, file, channels);
        return;
    }
    const bool shell = format == sbrt_grass::OutputFormat::shell;
    const sbrt::Frame &f = model.frame;
    const sbrt::Stats &s = model.stats;
    const double mib = 1024.0 * 1024.0;
    const double file_per_interval =
        s.intervals ? double(file.bytes) / double(s.intervals) : 0;
    const double file_compression =
        s.voxel_bytes ? 100.0 * (1.0 - double(file.bytes) / double(s.voxel_bytes)) : 0;
    const double memory_per_interval =
        s.intervals ? double(s.interval_bytes) / double(s.intervals) : 0;
    const double memory_per_cell = double(s.index_bytes) / double(f.cells());
    if (shell) {
        fprintf(stdout,
                "name=%s\nnorth=%.15g\nsouth=%.15g\neast=%.15g\nwest=%.15g\n"
                "top=%.15g\nbottom=%.15g\nrows=%d\ncols=%d\ndepths=%d\n"
                "nsres=%.15g\newres=%.15g\ntbres=%.15g\nmaterials=%zu\n"
                "voxels=%llu\nvoxel_bytes=%llu\nsbrt_bytes=%llu\n"
                "intervals=%llu\nsolid_intervals=%llu\nmax_stack=%u\n"
                "mean_stack=%.6f\ncompression=%.3f\n"
                "memory_bytes_per_interval=%.4f\nmemory_index_bytes_per_cell=%.4f\n",
                sbrt::shell_word(name).c_str(), f.north, f.south, f.east, f.west, f.top, f.bottom,
                f.rows, f.cols, f.depths, f.ns_res(), f.ew_res(), f.tb_res(),
                model.materials.size() - 1, (unsigned long long)s.voxels,
                (unsigned long long)s.voxel_bytes,
                (unsigned long long)s.sbrt_bytes,
                (unsigned long long)s.intervals,
                (unsigned long long)s.solid_intervals, s.max_stack,
                s.mean_stack, s.compression_percent, memory_per_interval, memory_per_cell);
        fprintf(stdout,
                "format=%u.%u\nfile_bytes=%llu\nfile_bytes_per_interval=%.4f\n"
                "file_compression=%.3f\n",
                unsigned(file.major), unsigned(file.minor),
                (unsigned long long)file.bytes, file_per_interval, file_compression);
        fprintf(stdout, "vertical_datum=%s\n",
                sbrt::shell_word(model.vertical_datum).c_str());
        if (channels)
            print_channels(*channels, true);
        return;
    }
    fprintf(stdout, "SBRT:          %s\n", sbrt::printable(name).c_str());
    fprintf(stdout, "Extent:        N %.10g  S %.10g  E %.10g  W %.10g\n",
            f.north, f.south, f.east, f.west);
    fprintf(stdout, "Vertical:      T %.10g  B %.10g%s\n", f.top, f.bottom,
            model.vertical_datum.empty()
                ? ""
                : ("  (relative to " + sbrt::printable(model.vertical_datum) + ")").c_str());
    fprintf(stdout, "Grid:          %d rows x %d cols x %d depths\n", f.rows,
            f.cols, f.depths);
    fprintf(stdout, "Resolution:    ns %.10g  ew %.10g  tb %.10g\n",
            f.ns_res(), f.ew_res(), f.tb_res());
    fprintf(stdout, "Materials:     %zu\n", model.materials.size() - 1);
    // by class id, with the colours a render draws (own or the palette's)
    std::vector<uint32_t> order;
    for (uint32_t i = 1; i < model.materials.size(); ++i)
        order.push_back(i);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return model.materials[a].id < model.materials[b].id;
    });
    for (const uint32_t i : order) {
        const sbrt::Material &m = model.materials[i];
        const auto rgb = sbrt::material_color(model.materials, i);
        fprintf(stdout, "  %11d  %3d:%3d:%3d  %s\n", m.id, rgb[0], rgb[1], rgb[2],
                sbrt::printable(m.label).c_str());
    }
    fprintf(stdout, "Memory (papers' Table 1):\n");
    fprintf(stdout, "  voxels:            %llu\n", (unsigned long long)s.voxels);
    fprintf(stdout, "  voxel model:       %.2f MiB (4 bytes per voxel)\n",
            s.voxel_bytes / mib);
    fprintf(stdout, "  SBRT in memory:    %.2f MiB (%.2f bytes per interval, %.2f per cell)\n",
            s.sbrt_bytes / mib, memory_per_interval, memory_per_cell);
    fprintf(stdout, "  intervals:         %llu (%llu solid)\n",
            (unsigned long long)s.intervals,
            (unsigned long long)s.solid_intervals);
    fprintf(stdout, "  max stack size:    %u\n", s.max_stack);
    fprintf(stdout, "  mean stack size:   %.2f\n", s.mean_stack);
    fprintf(stdout, "  compression:       %.1f %%\n", s.compression_percent);
    fprintf(stdout, "On disk (format %u.%u):\n", unsigned(file.major), unsigned(file.minor));
    fprintf(stdout, "  stacks file:       %.2f MiB (%.2f bytes per interval)\n",
            file.bytes / mib, file_per_interval);
    fprintf(stdout, "  compression:       %.1f %%\n", file_compression);
    if (channels)
        print_channels(*channels, false);
}
