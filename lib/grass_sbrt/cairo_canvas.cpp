/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Drawing the modules' PNG figures with cairo
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "cairo_canvas.hpp"

#include <cmath>
#include <cstdio>

#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt_grass {

Canvas::Canvas(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)),
      cr_(cairo_create(surface_)), width_(width), height_(height)
{
    if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
        const std::string why = cairo_status_to_string(cairo_status(cr_));
        cairo_destroy(cr_);
        cairo_surface_destroy(surface_);
        throw sbrt::Error("cannot draw a " + std::to_string(width) + " x " +
                          std::to_string(height) + " PNG: " + why);
    }
    select_font(cr_);
}

Canvas::~Canvas()
{
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
}

uint32_t *Canvas::row(int r) const
{
    return reinterpret_cast<uint32_t *>(cairo_image_surface_get_data(surface_) +
                                        size_t(r) * size_t(cairo_image_surface_get_stride(surface_)));
}

void Canvas::store(uint8_t *rgb, int rows, int cols)
{
    cairo_surface_flush(surface_);
    for (int r = 0; r < rows; ++r) {
        const uint32_t *px = row(r);
        for (int c = 0; c < cols; ++c, rgb += 3) {
            rgb[0] = uint8_t(px[c] >> 16);
            rgb[1] = uint8_t(px[c] >> 8);
            rgb[2] = uint8_t(px[c]);
        }
    }
}

std::string legend_text(const LegendClass &c)
{
    return c.label.empty() ? "class " + std::to_string(c.id) : c.label;
}

void draw_legend_entry(cairo_t *cr, const LegendClass &c, double x, double y, double font,
                       double pad)
{
    const double swatch = std::round(font);
    cairo_rectangle(cr, std::round(x) + 0.5, std::round(y - 0.9 * font) + 0.5, swatch, swatch);
    cairo_set_source_rgb(cr, c.color[0] / 255.0, c.color[1] / 255.0, c.color[2] / 255.0);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x + font + pad, y);
    show_text(cr, legend_text(c));
}

void select_font(cairo_t *cr, bool bold)
{
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
}

double text_width(cairo_t *cr, const std::string &text)
{
    return text_extents(cr, text).x_advance;
}

void show_text(cairo_t *cr, const std::string &text)
{
    cairo_show_text(cr, sbrt::valid_utf8(text).c_str());
}

cairo_text_extents_t text_extents(cairo_t *cr, const std::string &text)
{
    cairo_text_extents_t extents;
    cairo_text_extents(cr, sbrt::valid_utf8(text).c_str(), &extents);
    return extents;
}

void draw_north_arrow(cairo_t *cr, glm::dvec2 north, glm::dvec2 centre, double length,
                      double font, double scale)
{
    const glm::dvec2 d = north, n(-north.y, north.x);
    const glm::dvec2 tip = centre + 0.5 * length * d, tail = centre - 0.5 * length * d;
    const glm::dvec2 base = tip - 0.4 * length * d;
    const glm::dvec2 left = base + 0.22 * length * n, right = base - 0.22 * length * n;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_width(cr, 2 * scale);
    cairo_move_to(cr, tail.x, tail.y);
    cairo_line_to(cr, base.x, base.y);
    cairo_stroke(cr);
    cairo_move_to(cr, tip.x, tip.y);
    cairo_line_to(cr, left.x, left.y);
    cairo_line_to(cr, right.x, right.y);
    cairo_close_path(cr);
    cairo_fill(cr);

    select_font(cr, true);
    cairo_text_extents_t e;
    cairo_text_extents(cr, "N", &e);
    const glm::dvec2 at = tip + (0.8 * font) * d;
    cairo_move_to(cr, at.x - e.x_bearing - e.width / 2, at.y - e.y_bearing - e.height / 2);
    cairo_show_text(cr, "N");
    select_font(cr);
}

double nice_length(double most)
{
    const double ten = std::pow(10.0, std::floor(std::log10(most)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * ten <= most)
            return m * ten;
    return ten;
}

std::string length_text(double metres, bool in_metres)
{
    char text[32];
    if (!in_metres)
        std::snprintf(text, sizeof text, "%g map units", metres);
    else if (metres >= 1000)
        std::snprintf(text, sizeof text, "%g km", metres / 1000);
    else
        std::snprintf(text, sizeof text, "%g m", metres);
    return text;
}

} // namespace sbrt_grass
