/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The image as one raster map with exact colours, for the Map
 *            Display (the dialog's "add created map" adds <output>)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RGB_COMPOSITE_HPP
#define R3_SBRT_RGB_COMPOSITE_HPP

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "grass.hpp"

/// \brief A CELL map of the image with a colour table that gives back its
/// colours, as r.composite builds one (one rule per red-green pair, a ramp
/// of blue over 256 values) but without its levels where it can: with at
/// most MAX_EXACT_RULES red-green pairs in the image the value is red *
/// 65536 + green * 256 + blue and every colour is exact; with more, red
/// and green keep their upper 6 bits (within 2 levels; blue exact), since
/// GRASS's colour rules cost quadratic time in their number (65536 rules:
/// 3.5 s to build, 10 s to look up). Which is known once every row was
/// seen: close() then reads the image back from its red, green and blue
/// maps, a row at a time (holding the rows took 3 bytes a pixel: 357 MB
/// for a top view of 119 million cells, beyond memory=).
class RgbComposite {
public:
    static constexpr size_t MAX_EXACT_RULES = 4096;

    RgbComposite(const std::string &name, int cols);
    RgbComposite(const RgbComposite &) = delete;
    RgbComposite &operator=(const RgbComposite &) = delete;

    /// Notes the red-green pairs of one image row, 3 bytes per pixel.
    void add_row(const uint8_t *rgb);
    /// Writes the map, its rows read from the closed maps `bands` (red,
    /// green, blue, in the current mapset, of `window`), and its colour
    /// table; false where the colours are within 2 levels rather than
    /// exact.
    bool close(const std::array<std::string, 3> &bands, const struct Cell_head &window);
    const std::string &name() const { return name_; }

private:
    std::string name_;
    int cols_;
    std::vector<bool> red_green_; ///< 65536 flags
};

#endif
