/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   format=plain: a log per point as a borehole log reads, top to
 *            bottom, with the gaps (caves, air under overhangs) in place,
 *            elevations with their datum and depths below the surface
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>

#include "log_writers.hpp"
#include "util/safe_text.hpp"

namespace {

/// Decimals of the heights: 3, or as many as the voxel height has (up to
/// 9), so that voxel boundaries print exactly.
int height_decimals(const sbrt::Frame &frame)
{
    const double tb = frame.tb_res();
    for (int d = 3; d < 9; ++d) {
        const double scaled = tb * std::pow(10.0, d);
        if (std::fabs(scaled - std::round(scaled)) < 1e-6)
            return d;
    }
    return 9;
}

/// The point's first lines: where it is and what its column holds, from
/// which height down to which; the heights' unit and datum and the
/// surface the depths are measured from.
void write_heading(FILE *out, const LogSource &source, size_t index, const PointLog &p,
                   int decimals)
{
    std::fprintf(out, "Point %zu at %s, %s", index + 1, number_text(p.point.x).c_str(),
                 number_text(p.point.y).c_str());
    if (p.point.cat >= 0)
        std::fprintf(out, " (cat %d)", p.point.cat);
    if (!p.log) {
        std::fprintf(out, ": outside the model\n");
        return;
    }
    std::fprintf(out, ", row %d, col %d", p.log->cell.row, p.log->cell.col);
    if (p.log->is_empty()) {
        std::fprintf(out, ": empty (no layers)\n");
        return;
    }
    // the datum is another mapset's text: printable
    const std::string reference = sbrt::printable(elevation_reference(source));
    const size_t layers = p.log->layer_count();
    const size_t gaps = p.log->entries.size() - layers;
    std::fprintf(out, ": %zu layer%s", layers, layers == 1 ? "" : "s");
    if (gaps)
        std::fprintf(out, ", %zu gap%s", gaps, gaps == 1 ? "" : "s");
    std::fprintf(out, " from %.*f down to %.*f %s\n", decimals, p.log->entries.front().top,
                 decimals, p.log->entries.back().bottom, reference.c_str());
    std::fprintf(out, "Elevations in %s%s; depths below the surface at %.*f %s (the top "
                 "of the highest layer)\n",
                 reference.c_str(), vertical_datum(source).empty() ? " (no vertical datum)" : "",
                 decimals, *surface_of(p), reference.c_str());
}

/// The point's voxels, top down: heights, class ("-" in a cave) and each
/// channel's value ("*" for none, as r.what prints no data), in columns
/// as wide as the channels' names.
void write_voxel_table(FILE *out, const LogSource &source, const PointLog &p, int decimals)
{
    const int width = decimals + 10;
    std::fprintf(out, "Voxels with their property channels, top down:\n%*s %*s %6s",
                 width, "top", width, "bottom", "class");
    std::vector<int> widths;
    for (const sbrt::ChannelInfo &c : source.channels) {
        const std::string name = sbrt::printable(c.name);
        widths.push_back(std::max(8, int(name.size())));
        std::fprintf(out, " %*s", widths.back(), name.c_str());
    }
    std::fputc('\n', out);
    for (const sbrt::VoxelValues &v : p.voxels) {
        std::fprintf(out, "%*.*f %*.*f ", width, decimals, v.top, width, decimals, v.bottom);
        if (v.material == sbrt::EMPTY)
            std::fprintf(out, "%6s", "-");
        else
            std::fprintf(out, "%6d", material_of(source.model, v.material).id);
        for (size_t c = 0; c < v.values.size(); ++c)
            std::fprintf(out, " %*s", widths[c],
                         std::isnan(v.values[c]) ? "*"
                                                 : number_text(v.values[c]).c_str());
        std::fputc('\n', out);
    }
}

} // namespace

void write_plain_logs(FILE *out, const LogSource &source, const std::vector<PointLog> &logs)
{
    const sbrt::Model &model = source.model;
    const int decimals = height_decimals(model.frame());
    const int width = decimals + 10;
    for (size_t i = 0; i < logs.size(); ++i) {
        if (i)
            std::fputc('\n', out);
        const PointLog &p = logs[i];
        write_heading(out, source, i, p, decimals);
        if (!p.log || p.log->is_empty())
            continue;
        const double surface = *surface_of(p);
        std::fprintf(out, "%*s %*s %*s %*s %*s %6s  %s\n", width, "top", width, "bottom", width,
                     "thickness", width, "top depth", width, "bottom depth", "class", "label");
        for (const sbrt::LogEntry &e : p.log->entries) {
            std::fprintf(out, "%*.*f %*.*f %*.*f %*.*f %*.*f ", width, decimals, e.top, width,
                         decimals, e.bottom, width, decimals, e.thickness(), width, decimals,
                         surface - e.top + 0.0, width, decimals, surface - e.bottom);
            if (e.is_gap())
                std::fprintf(out, "%6s  %s\n", "", "(gap)");
            else
                std::fprintf(out, "%6d  %s\n", material_of(model, e.material).id,
                             sbrt::printable(material_of(model, e.material).label).c_str());
        }
        if (source.voxel_rows && !p.voxels.empty())
            write_voxel_table(out, source, p, decimals);
    }
}
