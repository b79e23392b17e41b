/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   SBRT -> 3D raster in the current 3D region (flag -r)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"
#include "grass_window.hpp"

#include <cstdlib>

#include "legend.hpp"
#include "raster_metadata.hpp"
#include "sbrt_store.hpp"
#include "builders/voxel_expander.hpp"

void sbrt_to_voxels(const char *input, const char *output, unsigned threads)
{
    sbrt::ReadOptions reading;
    reading.threads = threads;
    const sbrt::Model model = sbrt_grass::read_sbrt_map(input, reading);
    const sbrt::Frame target = sbrt_grass::current_frame();
    warn_if_other_grid(input, model.frame(), target);
    RASTER3D_Region region;
    Rast3d_get_window(&region);

    // FCELL holds every class id exactly up to 2^24
    bool fits_fcell = true;
    for (const sbrt::Material &m : model.materials())
        if (m.id != sbrt::NULL_CLASS && std::abs(int64_t(m.id)) > (1 << 24))
            fits_fcell = false;
    const int type = fits_fcell ? FCELL_TYPE : DCELL_TYPE;
    // as r3.mapcalc does: file type first, tiles of at most 32 KiB
    Rast3d_set_file_type(type);
    RASTER3D_Map *map = static_cast<RASTER3D_Map *>(
        Rast3d_open_new_opt_tile_size(output, RASTER3D_USE_CACHE_XY, &region,
                                      type, 32));
    if (!map)
        G_fatal_error(_("Unable to create 3D raster map <%s>"), output);

    sbrt::VoxelExpander expander(model, target);
    std::vector<int32_t> classes(target.cells());
    G_message(_("Expanding SBRT <%s> into 3D raster map <%s>..."), input,
              output);
    for (int z = 0; z < target.depths; ++z) {
        G_percent(z, target.depths, 2);
        expander.next_slice(classes.data());
        for (int row = 0; row < target.rows; ++row)
            for (int col = 0; col < target.cols; ++col) {
                const int32_t id = classes[size_t(row) * target.cols + col];
                FCELL f = FCELL(id);
                DCELL d = DCELL(id);
                void *v = type == FCELL_TYPE ? static_cast<void *>(&f)
                                             : static_cast<void *>(&d);
                if (id == sbrt::NULL_CLASS)
                    Rast3d_set_null_value(v, 1, type);
                if (!Rast3d_put_value(map, col, row, z, v, type))
                    G_fatal_error(_("Unable to write 3D raster map <%s>"),
                                  output);
            }
    }
    G_percent(1, 1, 1);
    if (!Rast3d_close(map))
        G_fatal_error(_("Unable to close 3D raster map <%s>"), output);

    struct Colors colors;
    sbrt_grass::make_colors(model.materials(), &colors);
    Rast3d_write_colors(output, G_mapset(), &colors);
    Rast_free_colors(&colors);
    struct Categories cats;
    sbrt_grass::make_cats(model.materials(), &cats, input);
    Rast3d_write_cats(output, &cats);
    Rast_free_cats(&cats);
    sbrt_grass::MapHistory history;
    history.data_source_1 = std::string("SBRT ") + input;
    sbrt_grass::write_raster3d_history(output, history);
}
