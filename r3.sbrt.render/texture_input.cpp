/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Drape texture from raster maps
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "texture_input.hpp"

#include <algorithm>
#include <cmath>

#include "grass.hpp"
#include "grass_color_rules.hpp"
#include "request_error.hpp"

namespace {

/// An open raster map (closed on scope exit).
class RasterInput {
public:
    explicit RasterInput(const std::string &name)
        : name_(name), mapset_(G_find_raster2(name.c_str(), ""))
    {
        if (!mapset_)
            bad_request(_("texture=: raster map <%s> not found"), name.c_str());
        fd_ = Rast_open_old(name.c_str(), mapset_);
    }
    ~RasterInput() { Rast_close(fd_); }
    RasterInput(const RasterInput &) = delete;
    RasterInput &operator=(const RasterInput &) = delete;

    int fd() const { return fd_; }
    const char *mapset() const { return mapset_; }
    const std::string &name() const { return name_; }

private:
    std::string name_;
    const char *mapset_;
    int fd_ = -1;
};

} // namespace

sbrt::Texture read_texture(const std::vector<std::string> &maps)
{
    // read at the first map's own grid, whatever the current region
    Cell_head own;
    {
        const char *mapset = G_find_raster2(maps[0].c_str(), "");
        if (!mapset)
            bad_request(_("texture=: raster map <%s> not found"), maps[0].c_str());
        Rast_get_cellhd(maps[0].c_str(), mapset, &own);
    }
    Rast_set_input_window(&own);
    sbrt::Texture t;
    t.north = own.north;
    t.south = own.south;
    t.east = own.east;
    t.west = own.west;
    t.rows = own.rows;
    t.cols = own.cols;
    const size_t cols = size_t(own.cols);
    t.rgb.assign(size_t(own.rows) * cols, {0, 0, 0});
    t.valid.assign(size_t(own.rows) * cols, 0);
    if (maps.size() == 1) {
        RasterInput in(maps[0]);
        GrassColors table; // freed whole, the lookup Rast_lookup_d_colors builds too
        Colors &colors = *table.get();
        if (Rast_read_colors(maps[0].c_str(), in.mapset(), &colors) < 0)
            bad_request(_("texture=%s has no colour table"), maps[0].c_str());
        std::vector<DCELL> row(cols);
        std::vector<unsigned char> r(cols), g(cols), b(cols), set(cols);
        for (int y = 0; y < own.rows; ++y) {
            Rast_get_d_row(in.fd(), row.data(), y);
            Rast_lookup_d_colors(row.data(), r.data(), g.data(), b.data(),
                                 set.data(), int(cols), &colors);
            for (size_t x = 0; x < cols; ++x) {
                const size_t i = size_t(y) * cols + x;
                t.rgb[i] = {r[x], g[x], b[x]};
                t.valid[i] = !Rast_is_d_null_value(&row[x]) && set[x];
            }
        }
    }
    else {
        std::fill(t.valid.begin(), t.valid.end(), 1);
        std::vector<DCELL> row(cols);
        for (int band = 0; band < 3; ++band) {
            RasterInput in(maps[size_t(band)]);
            for (int y = 0; y < own.rows; ++y) {
                Rast_get_d_row(in.fd(), row.data(), y);
                for (size_t x = 0; x < cols; ++x) {
                    const size_t i = size_t(y) * cols + x;
                    if (Rast_is_d_null_value(&row[x]))
                        t.valid[i] = 0;
                    else
                        t.rgb[i][size_t(band)] =
                            uint8_t(std::clamp(std::lround(row[x]), 0L, 255L));
                }
            }
        }
    }
    Rast_unset_window(); // back to one window (the region) for the outputs
    return t;
}
