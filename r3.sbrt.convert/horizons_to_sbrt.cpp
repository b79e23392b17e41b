/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   Stacked horizon rasters -> SBRT, row by row, no voxels
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>

#include "builders/horizon_builder.hpp"
#include "grass_window.hpp"
#include "legend.hpp"

namespace {

/// One 2D raster read row by row into doubles (NaN for null).
class RasterRows {
public:
    explicit RasterRows(const char *name)
    {
        fd_ = Rast_open_old(name, "");
        buffer_ = Rast_allocate_d_buf();
        values_.resize(Rast_window_cols());
    }
    ~RasterRows()
    {
        G_free(buffer_);
        Rast_close(fd_);
    }
    RasterRows(const RasterRows &) = delete;
    RasterRows &operator=(const RasterRows &) = delete;

    const double *read(int row)
    {
        Rast_get_d_row(fd_, buffer_, row);
        for (size_t c = 0; c < values_.size(); ++c)
            values_[c] = Rast_is_d_null_value(&buffer_[c]) ? NAN : buffer_[c];
        return values_.data();
    }

private:
    int fd_;
    DCELL *buffer_;
    std::vector<double> values_;
};

/// The 2D grid of the 3D region, so horizons are resampled onto it.
void use_3d_grid_for_2d_reads(const sbrt::Frame &f)
{
    struct Cell_head current;
    G_get_window(&current);
    Cell_head window = sbrt_grass::window_of(f, current);
    Rast_set_window(&window);
}

} // namespace

sbrt::Model horizons_to_sbrt(const std::vector<std::string> &horizons,
                             const std::vector<int> &materials,
                             const char *bottom)
{
    if (horizons.size() != materials.size())
        G_fatal_error(_("%zu horizons but %zu materials: give one material "
                        "id per horizon, top to bottom"),
                      horizons.size(), materials.size());
    const sbrt::Frame frame = sbrt_grass::current_frame();
    use_3d_grid_for_2d_reads(frame);

    std::vector<sbrt::Material> units;
    std::vector<std::unique_ptr<RasterRows>> tops;
    for (size_t i = 0; i < horizons.size(); ++i) {
        if (!G_find_raster2(horizons[i].c_str(), ""))
            G_fatal_error(_("Raster map <%s> not found"), horizons[i].c_str());
        tops.push_back(std::make_unique<RasterRows>(horizons[i].c_str()));
        sbrt::Material m;
        m.id = materials[i];
        m.label = horizons[i];
        units.push_back(m);
    }
    // bottom= is a raster map or a constant elevation
    std::unique_ptr<RasterRows> bottom_map;
    std::vector<double> bottom_value(frame.cols, NAN);
    if (bottom) {
        char *end = nullptr;
        const double z = std::strtod(bottom, &end);
        if (*bottom && *end == '\0' && std::isfinite(z))
            bottom_value.assign(frame.cols, z);
        else if (G_find_raster2(bottom, ""))
            bottom_map = std::make_unique<RasterRows>(bottom);
        else
            G_fatal_error(_("bottom=<%s> is neither a number nor a raster map"),
                          bottom);
    }

    sbrt::HorizonStackBuilder builder(frame, units);
    std::vector<const double *> row_tops(tops.size());
    for (int row = 0; row < frame.rows; ++row) {
        G_percent(row, frame.rows, 2);
        for (size_t i = 0; i < tops.size(); ++i)
            row_tops[i] = tops[i]->read(row);
        builder.add_row(row_tops, bottom_map ? bottom_map->read(row)
                                             : bottom_value.data());
    }
    G_percent(1, 1, 1);
    if (builder.clamped())
        G_warning(_("%llu horizon heights lay outside the 3D region's "
                    "vertical extent (b=%g, t=%g) and were clamped; set "
                    "g.region b= t= tbres= to cover them"),
                  (unsigned long long)builder.clamped(), frame.bottom,
                  frame.top);
    sbrt::Model model = builder.finish();
    if (model.stats().solid_intervals == 0)
        G_fatal_error(_("The horizons give no unit with thickness in the "
                        "current region"));
    return model;
}
