/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Drawing the modules' PNG figures with cairo: a canvas (RAII),
 *            text measures, a north arrow, lengths a person reads
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CAIRO_CANVAS_HPP
#define SBRT_CAIRO_CANVAS_HPP

#include <array>
#include <cstdint>
#include <string>

#include <cairo.h>
#include <glm/vec2.hpp>

namespace sbrt_grass {

/// \brief A cairo context drawing on an RGB image surface (RAII for both),
/// DejaVu Sans selected.
class Canvas {
public:
    Canvas(int width, int height);
    ~Canvas();
    Canvas(const Canvas &) = delete;
    Canvas &operator=(const Canvas &) = delete;

    cairo_t *cr() const { return cr_; }
    int width() const { return width_; }
    int height() const { return height_; }
    /// The surface's row `r` (xRGB words), to read or to set pixels in;
    /// call cairo_surface_mark_dirty via mark_dirty() after setting.
    uint32_t *row(int r) const;
    void mark_dirty() { cairo_surface_mark_dirty(surface_); }
    /// The first `rows` x `cols` pixels as packed rgb rows.
    void store(uint8_t *rgb, int rows, int cols);

private:
    cairo_surface_t *surface_;
    cairo_t *cr_;
    int width_, height_;
};

/// \brief One class a legend may show.
struct LegendClass {
    int32_t id;
    std::string label; ///< empty: the legend shows the id
    std::array<uint8_t, 3> color;
};

/// The class's label, or "class <id>" where it has none.
std::string legend_text(const LegendClass &c);
/// A legend's line: the class's colour as a square `font` pixels wide,
/// outlined, then its text `pad` pixels to the right, on baseline `y`.
void draw_legend_entry(cairo_t *cr, const LegendClass &c, double x, double y, double font,
                       double pad);

/// Selects DejaVu Sans, bold or not.
void select_font(cairo_t *cr, bool bold = false);
/// How far `text` advances at the current font.
double text_width(cairo_t *cr, const std::string &text);
/// cairo_show_text of `text` made valid UTF-8 first: one bad byte puts the
/// cairo context in an error state that draws nothing after it (issue 48,
/// item 9), and labels come from files another user may have written.
void show_text(cairo_t *cr, const std::string &text);
/// cairo_text_extents of `text` made valid UTF-8 first (as show_text).
cairo_text_extents_t text_extents(cairo_t *cr, const std::string &text);
/// An arrow `length` pixels long centred on `centre`, pointing along `north`
/// (unit, image directions: x right, y down): a shaft, a head, a bold N
/// beyond its tip at `font` pixels; lines `scale` pixels wide times two.
void draw_north_arrow(cairo_t *cr, glm::dvec2 north, glm::dvec2 centre, double length,
                      double font, double scale);
/// A "nice" length (1, 2 or 5 times a power of ten) of at most `most`.
double nice_length(double most);
/// "250 m", "2.5 km" (metres), or "250 map units" where not in metres.
std::string length_text(double metres, bool in_metres);

} // namespace sbrt_grass

#endif
