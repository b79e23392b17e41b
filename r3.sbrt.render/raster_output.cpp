/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Bands of the image -> raster maps (and a PNG file)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "raster_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "legend.hpp"
#include "property_colors.hpp"
#include "raster_metadata.hpp"

namespace {

void write_history(const std::string &name, const RenderRequest &request)
{
    sbrt_grass::MapHistory history;
    history.data_source_1 = "SBRT " + request.input;
    // a coarse frame is never written as if it were exact
    history.data_source_2 = request.coarse_note();
    sbrt_grass::write_raster_history(name.c_str(), history);
}

} // namespace

struct Cell_head image_window(const struct Cell_head &region, int rows, int cols)
{
    const double cell = std::min((region.east - region.west) / cols,
                                 (region.north - region.south) / rows);
    const double x = (region.east + region.west) / 2,
                 y = (region.north + region.south) / 2;
    struct Cell_head window = region;
    window.rows = window.rows3 = rows;
    window.cols = window.cols3 = cols;
    window.west = x - cell * cols / 2;
    window.east = x + cell * cols / 2;
    window.south = y - cell * rows / 2;
    window.north = y + cell * rows / 2;
    window.ew_res = window.ew_res3 = cell;
    window.ns_res = window.ns_res3 = cell;
    G_adjust_Cell_head(&window, 1, 1);
    return window;
}

struct Cell_head tile_window(struct Cell_head window, const std::array<int, 4> &tile)
{
    const auto [row, col, rows, cols] = tile;
    window.north -= row * window.ns_res;
    window.west += col * window.ew_res;
    window.south = window.north - rows * window.ns_res;
    window.east = window.west + cols * window.ew_res;
    window.rows = window.rows3 = rows;
    window.cols = window.cols3 = cols;
    return window;
}

int png_enlargement(const RenderRequest &request, int rows, int cols)
{
    if (request.view.kind != sbrt::ViewKind::top)
        return 1; // size= is the image
    if (request.size_given)
        return std::max(1, std::min(request.width / cols, request.height / rows));
    const int longer = std::max(rows, cols);
    return std::max(1, (MIN_TOP_VIEW_PNG_SIDE + longer - 1) / longer);
}

ImageMaps::ImageMaps(const RenderRequest &request, const struct Cell_head &window,
                     PngAnnotations annotations)
    : request_(request), window_(window), cols_(window.cols), cells_(size_t(window.cols)),
      dcells_(size_t(window.cols))
{
    // LZ4 writes faster than GRASS's default ZSTD, for larger maps
    // (docs/performance.md); an image is rendered again more often than it
    // is stored for long.
    // The user's GRASS_COMPRESSOR stays in force. (Before the raster
    // library's first call, which reads it.)
    setenv("GRASS_COMPRESSOR", "LZ4", 0);
    struct Cell_head output_window = window;
    Rast_set_output_window(&output_window);
    if (!request.output.empty()) {
        composite_ = std::make_unique<RgbComposite>(request.output, cols_);
        for (const char *band : {"red", "green", "blue"})
            rgb_.push_back(open(request.output + "." + band, CELL_TYPE));
    }
    if (!request.material.empty())
        material_.push_back(open(request.material, CELL_TYPE));
    if (!request.hit_elevation.empty())
        elevation_.push_back(open(request.hit_elevation, DCELL_TYPE));
    if (!request.depth.empty())
        depth_.push_back(open(request.depth, DCELL_TYPE));
    if (!request.value.empty())
        value_.push_back(open(request.value, DCELL_TYPE));
    if (!request.png.empty())
        png_ = std::make_unique<AnnotatedPng>(request.png, window.rows, cols_,
                                              std::move(annotations),
                                              png_enlargement(request, window.rows, cols_));
}

ImageMaps::Map ImageMaps::open(const std::string &name, RASTER_MAP_TYPE type)
{
    return {name, Rast_open_new(name.c_str(), type), type};
}

sbrt::Outputs ImageMaps::outputs() const
{
    const bool legend = png_ && png_->needs_classes();
    return {!material_.empty() || legend, !elevation_.empty(), !depth_.empty(),
            !value_.empty()};
}

void ImageMaps::write(const sbrt::Band &band)
{
    const size_t cols = size_t(cols_);
    for (int r = 0; r < band.rows; ++r) {
        const uint8_t *rgb_row = band.rgb.row(r);
        if (composite_)
            composite_->add_row(rgb_row);
        for (size_t k = 0; k < rgb_.size(); ++k) {
            const uint8_t *rgb = rgb_row + k;
            for (size_t c = 0; c < cols; ++c)
                cells_[c] = rgb[c * 3];
            Rast_put_c_row(rgb_[k].fd, cells_.data());
        }
        if (!material_.empty()) {
            const int32_t *material = band.material.row(r);
            for (size_t c = 0; c < cols; ++c) {
                if (material[c] == sbrt::NULL_CLASS)
                    Rast_set_c_null_value(&cells_[c], 1);
                else
                    cells_[c] = material[c];
            }
            Rast_put_c_row(material_[0].fd, cells_.data());
        }
        for (const auto &[maps, values] : {std::pair{&elevation_, &band.elevation},
                                          std::pair{&depth_, &band.depth},
                                          std::pair{&value_, &band.value}}) {
            if (maps->empty())
                continue;
            const double *v = values->row(r);
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
        png_->write(band);
}

void ImageMaps::close(const sbrt::Model &model, const sbrt::PropertyPaint *property)
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
    if (composite_) { // from the red, green and blue maps just closed
        if (!composite_->close({rgb_[0].name, rgb_[1].name, rgb_[2].name}, window_))
            G_verbose_message(_("<%s>: more than %zu red-green pairs; its colours are "
                                "within 2 levels of the image's (<%s.red>, .green, "
                                ".blue are exact)"),
                              composite_->name().c_str(), RgbComposite::MAX_EXACT_RULES,
                              request_.output.c_str());
        write_history(composite_->name(), request_);
    }
    if (png_)
        png_->finish();
    for (const Map &map : material_) {
        Rast_close(map.fd);
        sbrt_grass::write_class_legend(map.name.c_str(), model.materials(),
                                       request_.input.c_str());
        write_history(map.name, request_);
    }
    for (const auto *maps : {&elevation_, &depth_})
        for (const Map &map : *maps) {
            Rast_close(map.fd);
            write_history(map.name, request_);
        }
    for (const Map &map : value_) {
        Rast_close(map.fd);
        write_history(map.name, request_);
        if (!property)
            continue;
        // the colours of the image, the channel's unit and name
        struct Colors colors;
        Rast_init_colors(&colors);
        for (const sbrt::ColorRamp::Rule &rule : property->ramp().rules())
            Rast_add_d_color_rule(&rule.low.value, rule.low.rgb[0], rule.low.rgb[1],
                                  rule.low.rgb[2], &rule.high.value, rule.high.rgb[0],
                                  rule.high.rgb[1], rule.high.rgb[2], &colors);
        Rast_write_colors(map.name.c_str(), G_mapset(), &colors);
        Rast_free_colors(&colors);
        // the unit the legend shows ("%" for a sum of probabilities); it
        // and the name come from the model's file: cut to one line of what
        // GRASS keeps
        const std::string unit = property_unit(property->channels(), property->summed());
        if (!unit.empty())
            sbrt_grass::write_raster_units(map.name.c_str(), unit);
        sbrt_grass::put_raster_title(map.name.c_str(),
                                     "property " + request_.property_title());
    }
}
