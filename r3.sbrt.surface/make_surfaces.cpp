/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * PURPOSE:   The column loop: every region cell sampled at its centre in
 *            the model's grid, rows measured in parallel a block at a
 *            time and written in order
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cmath>
#include <vector>

#include "measure/centre_sampling.hpp"
#include "measure/class_set.hpp"
#include "measure/column_figures.hpp"
#include "measure/expected_thickness.hpp"
#include "model/class_names.hpp"
#include "sbrt_bands.hpp"
#include "sbrt_store.hpp"
#include "util/safe_text.hpp"
#include "surface.hpp"
#include "surface_maps.hpp"
#include "util/parallel.hpp"

namespace {

/// Rows measured together before they are written: 64, fewer in a region
/// so wide that 64 rows would hold more than 2^20 cells (40 MiB of figures).
int block_rows(int cols) { return std::max(1, std::min(64, (1 << 20) / std::max(1, cols))); }

/// A warning where no cell centre of the region falls in the model (a new
/// location's default region): every map would be null.
void warn_if_outside(const std::string &input, const sbrt::Frame &frame,
                     const struct Cell_head &region, const sbrt::CentreSampling &sampling)
{
    const auto inside = [](const std::vector<int> &cells) {
        return std::any_of(cells.begin(), cells.end(), [](int c) { return c >= 0; });
    };
    if (inside(sampling.model_row) && inside(sampling.model_col))
        return;
    G_warning(_("The current region (n=%.15g s=%.15g e=%.15g w=%.15g) misses SBRT <%s>, "
                "which covers n=%.15g s=%.15g e=%.15g w=%.15g: every cell of the maps is "
                "null. Set the region to the SBRT with r3.sbrt.convert -s sbrt=%s (or "
                "g.region to a part of it)"),
              region.north, region.south, region.east, region.west, input.c_str(),
              frame.north, frame.south, frame.east, frame.west, input.c_str());
}

} // namespace

void make_surfaces(const SurfaceRequest &request)
{
    struct Cell_head region;
    G_get_window(&region);
    // band by band within memory=; expected_thickness= reads the model
    // whole (its channels lie by the spans of every column)
    const bool whole = !request.expected_thickness.empty();
    sbrt_grass::SbrtBands bands(
        request.input, request.memory, request.threads,
        sbrt::MapArea{region.north, region.south, region.east, region.west}, whole);
    const sbrt::Frame frame = bands.frame();
    const std::vector<sbrt::Material> &materials = bands.materials();
    const bool by_classes = !request.classes.empty();
    // classes= by id, code, short name or label (sbrt::ClassNames)
    const sbrt::ClassSet set =
        by_classes ? sbrt::ClassSet::of_materials(
                         materials, sbrt::ClassNames(materials)
                                        .resolve(request.classes, "classes",
                                                 "SBRT <" + request.input + ">"))
                   : sbrt::ClassSet();
    const std::string described = by_classes ? set.describe(materials) : "";
    if (by_classes)
        G_verbose_message(_("Classes of the set: %s"), sbrt::printable(described).c_str());
    // expected_thickness=: the probability's channels (only their blocks
    // under the region are decoded)
    sbrt_grass::ProbabilityChannels probability;
    if (whole)
        probability = sbrt_grass::read_probability_channels(
            request.input.c_str(), bands.band_at(0), request.probability,
            "expected_thickness=");
    const sbrt::PropertyChannels *channels = probability.channels.get();
    const std::vector<size_t> &summed = probability.summed;
    const sbrt::CentreSampling sampling = sbrt::sample_at_centres(
        frame, {region.north, region.south, region.east, region.west, region.rows, region.cols});

    warn_if_outside(request.input, frame, region, sampling);

    SurfaceMaps maps(request, described, bands.vertical_datum(), region.cols);
    const size_t cols = size_t(region.cols);
    const int block = block_rows(region.cols);
    std::vector<sbrt::MapFigures> figures(size_t(block) * cols);
    std::vector<unsigned char> present(size_t(block) * cols);
    std::vector<double> expected(channels ? size_t(block) * cols : 0);
    const double voxel_height = frame.tb_res();
    for (int first = 0, rows = 0; first < region.rows; first += rows) {
        G_percent(first, region.rows, 2);
        rows = std::min(block, region.rows - first);
        // the model's rows of this pass, within one band
        const sbrt::Model *model = nullptr;
        const auto row_of = [&](int k) { return sampling.model_row[size_t(k)]; };
        int k = first;
        while (k < first + rows && row_of(k) < 0)
            ++k;
        if (k < first + rows) {
            model = &bands.band_at(row_of(k));
            while (k < first + rows && row_of(k) < bands.band_end())
                ++k;
            rows = k - first;
        }
        sbrt::for_each_row(rows, request.threads, [&](int k) {
            const int model_row = sampling.model_row[size_t(first + k)];
            for (size_t c = 0; c < cols; ++c) {
                const size_t at = size_t(k) * cols + c;
                const int model_col = sampling.model_col[c];
                present[at] = 0;
                if (channels)
                    expected[at] = NAN;
                if (model_row < 0 || model_col < 0)
                    continue;
                const uint64_t cell = bands.band_cell(model_row, model_col);
                if (channels)
                    expected[at] = sbrt::expected_thickness(*channels, summed, cell,
                                                            voxel_height);
                if (!by_classes)
                    continue;
                const sbrt::ColumnFigures f = sbrt::column_figures(*model, cell, set);
                if (!f.present())
                    continue;
                present[at] = 1;
                figures[at] = sbrt::map_figures(frame, f);
            }
        });
        for (int k = 0; k < rows; ++k)
            maps.put_row(figures.data() + size_t(k) * cols, present.data() + size_t(k) * cols,
                         channels ? expected.data() + size_t(k) * cols : nullptr);
    }
    G_percent(1, 1, 1);
    G_verbose_message(_("Read in %d band(s), the largest %.1f MB in memory"),
                      bands.bands_read(), double(bands.largest_band_bytes()) / (1 << 20));
    maps.close();
}
