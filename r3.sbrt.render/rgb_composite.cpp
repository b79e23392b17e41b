/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The image as one raster map with exact colours
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "rgb_composite.hpp"

#include <algorithm>

RgbComposite::RgbComposite(const std::string &name, int cols)
    : name_(name), cols_(cols), red_green_(65536, false)
{
}

void RgbComposite::add_row(const uint8_t *rgb)
{
    for (int c = 0; c < cols_; ++c)
        red_green_[size_t(rgb[3 * c] << 8 | rgb[3 * c + 1])] = true;
}

bool RgbComposite::close(const std::array<std::string, 3> &bands,
                         const struct Cell_head &window)
{
    const bool exact = size_t(std::count(red_green_.begin(), red_green_.end(), true)) <=
                       MAX_EXACT_RULES;
    // the value's red-green part: the pair, or its upper 6 + 6 bits
    auto pair_of = [exact](int red, int green) {
        return exact ? red << 8 | green : (red >> 2) << 6 | green >> 2;
    };
    // the bands read in the image's window (the output window), not the
    // region's
    struct Cell_head region, image = window;
    Rast_get_input_window(&region);
    Rast_set_input_window(&image);
    std::array<int, 3> in;
    std::array<std::vector<CELL>, 3> rows;
    for (size_t k = 0; k < 3; ++k) {
        in[k] = Rast_open_old(bands[k].c_str(), G_mapset());
        rows[k].resize(size_t(cols_));
    }
    const int fd = Rast_open_new(name_.c_str(), CELL_TYPE);
    std::vector<CELL> cells(static_cast<size_t>(cols_));
    std::vector<bool> pairs(65536, false);
    for (int row = 0; row < image.rows; ++row) {
        for (size_t k = 0; k < 3; ++k)
            Rast_get_c_row(in[k], rows[k].data(), row);
        for (size_t c = 0; c < cells.size(); ++c) {
            const int pair = pair_of(rows[0][c], rows[1][c]);
            pairs[size_t(pair)] = true;
            cells[c] = pair << 8 | rows[2][c];
        }
        Rast_put_c_row(fd, cells.data());
    }
    Rast_close(fd);
    for (const int band : in)
        Rast_close(band);
    Rast_set_input_window(&region);
    // GRASS interpolates inside a rule: blue = (0 * (high - v) + 255 * (v -
    // low)) / 255 = v - low exactly, red and green constant
    struct Colors colors;
    Rast_init_colors(&colors);
    for (int pair = 0; pair < 65536; ++pair) {
        if (!pairs[size_t(pair)])
            continue;
        const int red = exact ? pair >> 8 : (pair >> 6) * 4 + 2;
        const int green = exact ? pair & 255 : (pair & 63) * 4 + 2;
        const CELL low = pair << 8, high = low | 255;
        Rast_add_c_color_rule(&low, red, green, 0, &high, red, green, 255, &colors);
    }
    Rast_write_colors(name_.c_str(), G_mapset(), &colors);
    Rast_free_colors(&colors);
    return exact;
}
