/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   One property channel of an SBRT -> 3D raster in the current
 *            3D region (-r property=), sampled at the voxels' centres
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"
#include "grass_window.hpp"

#include <cmath>
#include <string>

#include "grass.hpp"
#include "raster_metadata.hpp"
#include "measure/centre_sampling.hpp"
#include "sbrt_store.hpp"

namespace {

/// Names of the channels, for an error message.
std::string channel_names(const sbrt::PropertyChannels &channels)
{
    std::string names;
    for (const sbrt::ChannelInfo &c : channels.infos())
        names += (names.empty() ? "" : ", ") + c.name;
    return names;
}

} // namespace

void channel_to_voxels(const char *input, const char *channel, const char *output,
                       unsigned threads)
{
    sbrt::ReadOptions reading;
    reading.threads = threads;
    const sbrt::Model model = sbrt_grass::read_sbrt_map(input, reading);
    const auto channels = sbrt_grass::read_channels_map(input, model);
    if (!channels)
        G_fatal_error(_("SBRT <%s> has no property channels: property=%s cannot be "
                        "expanded (import with properties= to keep them)"),
                      input, channel);
    const int index = channels->find(channel);
    if (index < 0)
        G_fatal_error(_("SBRT <%s> has no property channel '%s'; it has: %s"), input,
                      channel, channel_names(*channels).c_str());
    const sbrt::ChannelInfo &info = channels->info(size_t(index));
    const sbrt::Frame &f = model.frame();
    const sbrt::Frame target = sbrt_grass::current_frame();
    warn_if_other_grid(input, f, target);
    RASTER3D_Region region;
    Rast3d_get_window(&region);

    // raw values of 16 bits or less, and floats, are FCELL exactly; a
    // packed channel's meaning (raw * scale + offset) needs DCELL
    const bool packed = info.scale != 1 || info.offset != 0;
    const int type = packed ? DCELL_TYPE : FCELL_TYPE;
    Rast3d_set_file_type(type);
    RASTER3D_Map *map = static_cast<RASTER3D_Map *>(Rast3d_open_new_opt_tile_size(
        output, RASTER3D_USE_CACHE_XY, &region, type, 32));
    if (!map)
        G_fatal_error(_("Unable to create 3D raster map <%s>"), output);
    // the unit comes from the model's file: one line of what GRASS keeps
    if (!info.unit.empty())
        Rast3d_set_unit(map, sbrt_grass::metadata_line(info.unit, sbrt_grass::MAX_UNITS_BYTES)
                                 .c_str());

    const sbrt::CentreSampling at = sbrt::sample_at_centres(
        f, {target.north, target.south, target.east, target.west, target.rows, target.cols});
    G_message(_("Expanding property channel '%s' of SBRT <%s> into 3D raster map "
                "<%s>..."),
              channel, input, output);
    for (int z = 0; z < target.depths; ++z) {
        G_percent(z, target.depths, 2);
        const double centre = target.bottom + (z + 0.5) * target.tb_res();
        const double level = std::floor(f.local_z(centre));
        for (int row = 0; row < target.rows; ++row)
            for (int col = 0; col < target.cols; ++col) {
                const int mr = at.model_row[size_t(row)], mc = at.model_col[size_t(col)];
                float raw = 0;
                const bool has = mr >= 0 && mc >= 0 && level >= 0 && level < f.depths &&
                                 channels->value(size_t(index), model.cell_index(mr, mc),
                                                 uint32_t(level), raw) &&
                                 !info.is_fill(raw);
                FCELL fv = raw;
                DCELL dv = info.physical(raw);
                void *v = type == FCELL_TYPE ? static_cast<void *>(&fv)
                                             : static_cast<void *>(&dv);
                if (!has)
                    Rast3d_set_null_value(v, 1, type);
                if (!Rast3d_put_value(map, col, row, z, v, type))
                    G_fatal_error(_("Unable to write 3D raster map <%s>"), output);
            }
    }
    G_percent(1, 1, 1);
    if (!Rast3d_close(map))
        G_fatal_error(_("Unable to close 3D raster map <%s>"), output);
    sbrt_grass::MapHistory history;
    history.data_source_1 = std::string("SBRT ") + input + " property channel " + channel;
    history.keywords = info.long_name;
    sbrt_grass::write_raster3d_history(output, history);
}
