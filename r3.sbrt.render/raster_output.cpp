/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Bands of the image -> raster maps (and a PNG file)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "raster_output.hpp"

#include <cmath>
#include <cstdlib>

#include "legend.hpp"

namespace {

void write_history(const std::string &name, const RenderRequest &request)
{
    struct History history;
    Rast_short_history(name.c_str(), "raster", &history);
    Rast_command_history(&history);
    Rast_format_history(&history, HIST_DATSRC_1, "SBRT %s", request.input.c_str());
    Rast_write_history(name.c_str(), &history);
}

} // namespace

ImageMaps::ImageMaps(const RenderRequest &request, int rows, int cols)
    : request_(request), cols_(cols), cells_(size_t(cols)), dcells_(size_t(cols))
{
    // Measured on B, 1056 x 884 (three RGB maps): LZ4 writes in 100 ms of
    // render against 125 with GRASS's default ZSTD, for 444 KB against 326
    // KB; an image is rendered again more often than it is stored for long.
    // The user's GRASS_COMPRESSOR stays in force.
    setenv("GRASS_COMPRESSOR", "LZ4", 0);
    for (const char *band : {"red", "green", "blue"})
        rgb_.push_back(open(request.output + "." + band, CELL_TYPE));
    if (!request.material.empty())
        material_.push_back(open(request.material, CELL_TYPE));
    if (!request.hit_elevation.empty())
        elevation_.push_back(open(request.hit_elevation, DCELL_TYPE));
    if (!request.depth.empty())
        depth_.push_back(open(request.depth, DCELL_TYPE));
    if (!request.png.empty())
        png_ = std::make_unique<sbrt::PngFile>(request.png, rows, cols);
}

ImageMaps::Map ImageMaps::open(const std::string &name, RASTER_MAP_TYPE type)
{
    return {name, Rast_open_new(name.c_str(), type), type};
}

sbrt::Outputs ImageMaps::outputs() const
{
    return {!material_.empty(), !elevation_.empty(), !depth_.empty()};
}

void ImageMaps::write(const sbrt::Band &band)
{
    const size_t cols = size_t(cols_);
    for (int r = 0; r < band.rows; ++r) {
        const size_t row = size_t(r) * cols;
        for (size_t k = 0; k < 3; ++k) {
            const uint8_t *rgb = band.rgb.data() + row * 3 + k;
            for (size_t c = 0; c < cols; ++c)
                cells_[c] = rgb[c * 3];
            Rast_put_c_row(rgb_[k].fd, cells_.data());
        }
        if (!material_.empty()) {
            const int32_t *material = band.material.data() + row;
            for (size_t c = 0; c < cols; ++c) {
                if (material[c] == sbrt::NULL_CLASS)
                    Rast_set_c_null_value(&cells_[c], 1);
                else
                    cells_[c] = material[c];
            }
            Rast_put_c_row(material_[0].fd, cells_.data());
        }
        for (const auto &[maps, values] : {std::pair{&elevation_, &band.elevation},
                                          std::pair{&depth_, &band.depth}}) {
            if (maps->empty())
                continue;
            const double *v = values->data() + row;
            for (size_t c = 0; c < cols; ++c) {
                if (std::isnan(v[c]))
                    Rast_set_d_null_value(&dcells_[c], 1);
                else
                    dcells_[c] = v[c];
            }
            Rast_put_d_row((*maps)[0].fd, dcells_.data());
        }
    }
    if (png_)
        png_->write_rows(band.rgb.data(), band.rows);
}

void ImageMaps::close(const sbrt::Model &model)
{
    for (const Map &map : rgb_) {
        Rast_close(map.fd);
        struct Colors colors;
        Rast_init_colors(&colors);
        Rast_make_grey_scale_colors(&colors, 0, 255);
        Rast_write_colors(map.name.c_str(), G_mapset(), &colors);
        Rast_free_colors(&colors);
        write_history(map.name, request_);
    }
    if (png_)
        png_->finish();
    for (const Map &map : material_) {
        Rast_close(map.fd);
        struct Colors colors;
        sbrt_grass::make_colors(model.materials(), &colors);
        Rast_write_colors(map.name.c_str(), G_mapset(), &colors);
        Rast_free_colors(&colors);
        struct Categories cats;
        sbrt_grass::make_cats(model.materials(), &cats, request_.input.c_str());
        Rast_write_cats(map.name.c_str(), &cats);
        Rast_free_cats(&cats);
        write_history(map.name, request_);
    }
    for (const auto *maps : {&elevation_, &depth_})
        for (const Map &map : *maps) {
            Rast_close(map.fd);
            write_history(map.name, request_);
        }
}
