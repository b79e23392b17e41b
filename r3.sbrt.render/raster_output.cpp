/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Image -> raster maps (and a PNG file)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "raster_output.hpp"

#include <cmath>
#include <functional>

#include "legend.hpp"
#include "png_writer.hpp"

namespace {

void write_history(const std::string &name, const RenderRequest &request)
{
    struct History history;
    Rast_short_history(name.c_str(), "raster", &history);
    Rast_command_history(&history);
    Rast_format_history(&history, HIST_DATSRC_1, "SBRT %s",
                        request.input.c_str());
    Rast_write_history(name.c_str(), &history);
}

/// One map, row by row; `value(i)` gives pixel i's value (NaN/NULL: null).
template <typename Value>
void write_map(const std::string &name, RASTER_MAP_TYPE type, int rows,
               int cols, const std::function<Value(size_t)> &value)
{
    const int fd = Rast_open_new(name.c_str(), type);
    void *buffer = Rast_allocate_buf(type);
    for (int row = 0; row < rows; ++row) {
        for (int col = 0; col < cols; ++col) {
            const size_t i = size_t(row) * cols + col;
            const Value v = value(i);
            void *cell = G_incr_void_ptr(buffer, size_t(col) * Rast_cell_size(type));
            if (type == CELL_TYPE) {
                if (double(v) == double(sbrt::NULL_CLASS))
                    Rast_set_c_null_value(static_cast<CELL *>(cell), 1);
                else
                    *static_cast<CELL *>(cell) = CELL(v);
            }
            else if (std::isnan(double(v)))
                Rast_set_d_null_value(static_cast<DCELL *>(cell), 1);
            else
                *static_cast<DCELL *>(cell) = double(v);
        }
        Rast_put_row(fd, buffer, type);
    }
    G_free(buffer);
    Rast_close(fd);
}

} // namespace

void write_image_maps(const RenderRequest &request, const sbrt::Model &model,
                      const sbrt::Image &image)
{
    const char *bands[3] = {"red", "green", "blue"};
    for (int k = 0; k < 3; ++k) {
        const std::string name = request.output + "." + bands[k];
        write_map<int>(name, CELL_TYPE, image.rows, image.cols,
                       [&](size_t i) { return int(image.rgb[i * 3 + k]); });
        struct Colors colors;
        Rast_init_colors(&colors);
        Rast_make_grey_scale_colors(&colors, 0, 255);
        Rast_write_colors(name.c_str(), G_mapset(), &colors);
        Rast_free_colors(&colors);
        write_history(name, request);
    }
    if (!request.png.empty())
        sbrt::write_png(request.png, image.rows, image.cols, image.rgb);
    if (!request.material.empty()) {
        write_map<int>(request.material, CELL_TYPE, image.rows, image.cols,
                       [&](size_t i) { return image.material[i]; });
        struct Colors colors;
        sbrt_grass::make_colors(model.materials(), &colors);
        Rast_write_colors(request.material.c_str(), G_mapset(), &colors);
        Rast_free_colors(&colors);
        struct Categories cats;
        sbrt_grass::make_cats(model.materials(), &cats, request.input.c_str());
        Rast_write_cats(request.material.c_str(), &cats);
        Rast_free_cats(&cats);
        write_history(request.material, request);
    }
    if (!request.hit_elevation.empty()) {
        write_map<double>(request.hit_elevation, DCELL_TYPE, image.rows,
                          image.cols, [&](size_t i) { return image.elevation[i]; });
        write_history(request.hit_elevation, request);
    }
    if (!request.depth.empty()) {
        write_map<double>(request.depth, DCELL_TYPE, image.rows, image.cols,
                          [&](size_t i) { return image.depth[i]; });
        write_history(request.depth, request);
    }
}
