/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   3D raster -> SBRT, streamed slice by slice
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include "util/error.hpp"
#include "grass_window.hpp"
#include "legend.hpp"
#include "raster3d_slices.hpp"
#include "builders/voxel_builder.hpp"

std::vector<sbrt::Material> rule_legend(const sbrt::Classifier &classifier)
{
    std::vector<sbrt::Material> legend;
    for (const sbrt::ClassRule &rule : classifier.rules()) {
        sbrt::Material m;
        m.id = rule.id;
        m.label = rule.label;
        legend.push_back(m);
    }
    return legend;
}

sbrt::Model voxels_to_sbrt(const char *input, sbrt::Classifier &classifier)
{
    const char *mapset = G_find_raster3d(input, "");
    if (!mapset)
        G_fatal_error(_("3D raster map <%s> not found"), input);
    RASTER3D_Region window;
    Rast3d_get_window(&window);
    const sbrt::Frame frame = sbrt_grass::current_frame();
    Raster3dSlices slices(input, mapset, window);
    G_verbose_message(slices.reads_tiles()
                          ? _("Reading whole tiles (region = map's region)")
                          : _("Resampling into the current 3D region"));

    sbrt::VoxelStackBuilder builder(frame);
    std::vector<int32_t> classes(frame.cells());
    G_message(_("Converting 3D raster map <%s> (%d x %d x %d voxels)..."),
              input, frame.cols, frame.rows, frame.depths);
    for (int z = 0; z < frame.depths; ++z) {
        G_percent(z, frame.depths, 2);
        const double *values = slices.read(z);
        try {
            for (size_t i = 0; i < classes.size(); ++i)
                classes[i] = classifier.classify(values[i]);
        }
        catch (const sbrt::Error &e) {
            G_fatal_error(_("3D raster map <%s>, depth %d: %s"), input, z + 1,
                          e.what());
        }
        builder.add_slice(classes.data());
    }
    G_percent(1, 1, 1);
    if (classifier.unmatched())
        G_warning(_("%llu voxels matched no rule and became empty"),
                  (unsigned long long)classifier.unmatched());

    // legend: the map's categories and colours, labels of rules first
    sbrt::Model model = builder.finish(rule_legend(classifier));
    if (model.stats().solid_intervals == 0)
        G_fatal_error(_("3D raster map <%s> has only null cells in the "
                        "current 3D region; check g.region -p3"),
                      input);
    sbrt_grass::read_raster3d_legend(input, mapset, model.materials());
    return model;
}
