/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The PNG of a render with its legend, north arrow, vertical
 *            exaggeration and scale bar
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "png_annotations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <cairo.h>

#include "cairo_canvas.hpp"
#include "util/error.hpp"
#include "model/model.hpp"

using sbrt_grass::Canvas;
using sbrt_grass::legend_text;
using sbrt_grass::length_text;
using sbrt_grass::nice_length;
using sbrt_grass::select_font;
using sbrt_grass::show_text;
using sbrt_grass::text_width;

namespace {

/// Rows of the side panel drawn at once.
constexpr int PANEL_STRIP_ROWS = 256;

/// Sizes in pixels, grown with the image from those of a 480-row one
/// (never smaller: a 12-pixel font is the least that reads).
struct Layout {
    explicit Layout(int rows)
        : scale(std::clamp(rows / 480.0, 1.0, 4.0)), font(12 * scale),
          line(1.5 * font), pad(8 * scale), arrow(34 * scale),
          bar(6 * scale)
    {
    }
    double scale, font, line, pad, arrow, bar;
};

/// A bar of four black and white parts, its bottom-left corner at (x,
/// bottom), with its length below; `length` pixels.
void draw_scale_bar(cairo_t *cr, const Layout &l, double length, const std::string &text,
                    double x, double bottom)
{
    const double left = std::round(x), top = std::round(bottom - l.line - l.bar);
    for (int part = 0; part < 4; ++part) {
        cairo_rectangle(cr, left + part * length / 4, top, length / 4, l.bar);
        const double shade = part % 2 ? 1 : 0;
        cairo_set_source_rgb(cr, shade, shade, shade);
        cairo_fill(cr);
    }
    cairo_rectangle(cr, left, top, length, l.bar);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    cairo_move_to(cr, left, bottom - 0.4 * l.font);
    show_text(cr, "0 - " + text);
}

/// The panel's contents, measured before it is drawn.
struct Panel {
    Panel(cairo_t *cr, const Layout &l, const PngAnnotations &a,
          std::vector<const LegendClass *> shown, int cols, int rows)
        : shown(std::move(shown))
    {
        cairo_set_font_size(cr, l.font);
        if (a.zexag) {
            char text[64];
            std::snprintf(text, sizeof text, "Vertical exaggeration %g\u00d7", *a.zexag);
            zexag = text;
        }
        if (a.metres_per_pixel) {
            // a nice length of at most a quarter of the image, 120 pt
            const double most =
                std::min(0.25 * cols, 120 * l.scale) * *a.metres_per_pixel;
            const double metres = nice_length(most);
            scale_text = length_text(metres, a.scale_in_metres);
            scale_length = std::round(metres / *a.metres_per_pixel);
        }
        double bottom = l.pad;
        if (a.north)
            bottom += l.arrow + 2 * l.font + l.pad;
        if (!zexag.empty())
            bottom += l.line;
        if (!scale_text.empty())
            bottom += l.line + l.bar + l.pad;
        bottom_height = bottom;
        // every class and the title, or the colour bar at its full height
        needed_rows = int(std::ceil(bottom_height + 2 * l.pad +
                                    (a.bar ? 5 * l.line + 220 * l.scale + l.pad
                                           : double(this->shown.size() + 1) * l.line)));
        // the title, the classes that fit, a line saying how many more
        const int lines = int(std::floor((rows - bottom_height - 2 * l.pad) / l.line));
        if (lines < 2 || this->shown.empty())
            this->shown.clear();
        else if (int(this->shown.size()) + 1 > lines) {
            more = this->shown.size() - size_t(lines - 2);
            this->shown.resize(size_t(lines - 2));
        }
        if (a.bar) { // title, long name, unit, then the bar and its ends
        bar_lines = 3;
        bar_height = std::max(0.0, std::min(220 * l.scale, rows - bottom_height -
                                                               (bar_lines + 2) * l.line -
                                                               3 * l.pad));
        if (bar_height < 2 * l.line)
            bar_height = 0;
    }
    double w = std::max({text_width(cr, zexag),
                             text_width(cr, "0 - " + scale_text), scale_length,
                             l.arrow + 2 * l.font});
        for (const LegendClass *c : this->shown)
            w = std::max(w, l.font + l.pad + text_width(cr, legend_text(*c)));
        if (more)
            w = std::max(w, text_width(cr, more_text()));
        w = std::max(w, text_width(cr, a.caption));
        select_font(cr, true);
        if (!this->shown.empty() || a.bar)
            w = std::max(w, text_width(cr, a.title));
        if (a.bar) {
            select_font(cr);
            w = std::max({w, text_width(cr, bar_heading(*a.bar)), text_width(cr, bar_unit(*a.bar)),
                          2 * l.font + l.pad + text_width(cr, value_text(a.bar->high)),
                          2 * l.font + l.pad + text_width(cr, value_text(a.bar->low)),
                          l.font + l.pad + text_width(cr, "no value")});
        }
        select_font(cr);
        width = int(std::ceil(w + 2 * l.pad));
    }
    std::string more_text() const { return "+ " + std::to_string(more) + " more"; }
    static std::string bar_heading(const ColorBar &b)
    {
        return b.long_name.empty() ? b.name : b.long_name + " (" + b.name + ")";
    }
    static std::string bar_unit(const ColorBar &b)
    {
        return b.unit.empty() ? "" : "[" + b.unit + "]";
    }
    static std::string value_text(double v)
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.4g", v);
        return text;
    }
    int bar_lines = 0;
    double bar_height = 0;

    std::vector<const LegendClass *> shown;
    size_t more = 0;
    std::string zexag, scale_text;
    double scale_length = 0, bottom_height = 0;
    int width = 0;
    int needed_rows = 0; ///< the panel's height with nothing left out
};

/// The legend's title (the model's name) in bold at baseline `y`; the
/// font is normal again after it.
void draw_title(cairo_t *cr, const PngAnnotations &a, double x, double y)
{
    select_font(cr, true);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x, y);
    show_text(cr, a.title);
    select_font(cr);
}

/// A property's legend below the title at baseline `y`: its name and unit,
/// a vertical bar (high at the top) with its ends' values, and the colour
/// of hits without a value.
void draw_color_bar(cairo_t *cr, const Layout &l, const PngAnnotations &a, const Panel &p,
                    double x, double y)
{
    const ColorBar &b = *a.bar;
    draw_title(cr, a, x, y);
    y += l.line;
    cairo_move_to(cr, x, y);
    show_text(cr, Panel::bar_heading(b));
    if (!b.unit.empty()) {
        y += l.line;
        cairo_move_to(cr, x, y);
        show_text(cr, Panel::bar_unit(b));
    }
    if (p.bar_height <= 0 || b.colors.empty())
        return;
    const double top = std::round(y + l.pad), width = std::round(1.5 * l.font);
    const int height = int(p.bar_height);
    for (int r = 0; r < height; ++r) { // row r from the top: high to low
        const double f = height > 1 ? 1 - double(r) / (height - 1) : 0;
        const auto &c = b.colors[size_t(std::lround(f * double(b.colors.size() - 1)))];
        cairo_set_source_rgb(cr, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
        cairo_rectangle(cr, std::round(x), top + r, width, 1);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, std::round(x) + 0.5, top + 0.5, width - 1, height - 1);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x + width + l.pad, top + 0.8 * l.font);
    show_text(cr, Panel::value_text(b.high));
    cairo_move_to(cr, x + width + l.pad, top + height);
    show_text(cr, Panel::value_text(b.low));
    // no value
    const double swatch = std::round(l.font), row = top + height + l.line;
    cairo_rectangle(cr, std::round(x) + 0.5, std::round(row - 0.9 * l.font) + 0.5, swatch,
                    swatch);
    cairo_set_source_rgb(cr, b.no_value[0] / 255.0, b.no_value[1] / 255.0,
                         b.no_value[2] / 255.0);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x + l.font + l.pad, row);
    show_text(cr, "no value");
}

void draw_panel(cairo_t *cr, const Layout &l, const PngAnnotations &a, const Panel &p,
                int rows)
{
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 1);
    cairo_move_to(cr, 0.5, 0);
    cairo_line_to(cr, 0.5, rows);
    cairo_stroke(cr);
    cairo_set_font_size(cr, l.font);

    // legend from the top; baselines 0.3 font above a line's bottom
    const double x = l.pad;
    double y = l.pad + l.line - 0.3 * l.font;
    if (!p.shown.empty())
        draw_title(cr, a, x, y);
    for (const LegendClass *c : p.shown) {
        y += l.line;
        sbrt_grass::draw_legend_entry(cr, *c, x, y, l.font, l.pad);
    }
    if (p.more) {
        y += l.line;
        cairo_move_to(cr, x, y);
        show_text(cr, p.more_text());
    }
    if (a.bar)
        draw_color_bar(cr, l, a, p, x, y);
    else if (!a.caption.empty()) {
        y += l.line;
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, x, y);
        show_text(cr, a.caption);
    }

    // from the bottom up: scale bar, exaggeration, north arrow
    double bottom = rows - l.pad;
    if (!p.scale_text.empty()) {
        draw_scale_bar(cr, l, p.scale_length, p.scale_text, x, bottom);
        bottom -= l.line + l.bar + l.pad;
    }
    if (!p.zexag.empty()) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_move_to(cr, x, bottom - 0.3 * l.font);
        show_text(cr, p.zexag);
        bottom -= l.line;
    }
    if (a.north)
        sbrt_grass::draw_north_arrow(
            cr, *a.north, {x + l.font + l.arrow / 2, bottom - l.pad - l.font - l.arrow / 2},
            l.arrow, l.font, l.scale);
}

} // namespace

AnnotatedPng::AnnotatedPng(const std::string &path, int rows, int cols,
                           PngAnnotations annotations, int enlarge)
    : path_(path), rows_(rows * enlarge), cols_(cols * enlarge), enlarge_(enlarge),
      annotations_(std::move(annotations)), seen_(annotations_.classes.size(), false)
{
    if (enlarge < 1)
        throw sbrt::Error("a PNG's enlargement must be a whole number of at least 1");
    if (annotations_.metres_per_pixel)
        *annotations_.metres_per_pixel /= enlarge;
    if (!annotated()) {
        png_.emplace(path, rows_, cols_);
        row_.resize(size_t(cols_) * 3);
        return;
    }
    // fail now, not after the render, where the file cannot be written
    sbrt::PngFile(path, 1, 1);
    image_.resize(size_t(rows_) * size_t(cols_) * 3);
    for (size_t i = 0; i < annotations_.classes.size(); ++i)
        class_index_.emplace(annotations_.classes[i].id, i);
}

void AnnotatedPng::count_classes(const sbrt::Band &band)
{
    if (!needs_classes())
        return;
    if (band.material.empty())
        throw sbrt::Error("the PNG's legend needs the class of each pixel");
    int32_t last = sbrt::NULL_CLASS;
    for (int r = 0; r < band.rows; ++r) {
        const int32_t *row = band.material.row(r);
        for (int c = 0; c < band.cols; ++c) {
            const int32_t id = row[c];
            if (id == last || id == sbrt::NULL_CLASS)
                continue;
            last = id;
            const auto found = class_index_.find(id);
            if (found != class_index_.end())
                seen_[found->second] = true;
        }
    }
}

void AnnotatedPng::write_enlarged(const sbrt::Band &band)
{
    const int band_cols = cols_ / enlarge_;
    for (int r = 0; r < band.rows; ++r) {
        const uint8_t *in = band.rgb.row(r);
        uint8_t *out = png_ ? row_.data()
                            : image_.data() + size_t(band.first_row + r) * size_t(enlarge_) *
                                                  size_t(cols_) * 3;
        for (int c = 0; c < band_cols; ++c)
            for (int k = 0; k < enlarge_; ++k)
                std::copy_n(in + size_t(c) * 3, 3, out + (size_t(c) * enlarge_ + k) * 3);
        for (int k = 0; k < enlarge_; ++k) {
            if (png_)
                png_->write_rows(row_.data(), 1);
            else if (k > 0)
                std::copy_n(out, size_t(cols_) * 3, out + size_t(k) * size_t(cols_) * 3);
        }
    }
}

void AnnotatedPng::write(const sbrt::Band &band)
{
    if (png_ && enlarge_ == 1) {
        for (int r = 0; r < band.rows; ++r)
            png_->write_rows(band.rgb.row(r), 1);
        return;
    }
    count_classes(band);
    write_enlarged(band);
}

void AnnotatedPng::finish()
{
    if (png_) {
        png_->finish();
        return;
    }
    std::vector<const LegendClass *> shown;
    for (size_t i = 0; i < seen_.size(); ++i)
        if (seen_[i])
            shown.push_back(&annotations_.classes[i]);
    // by class id, as a legend is read (materials are numbered as met)
    std::stable_sort(shown.begin(), shown.end(),
                     [](const LegendClass *a, const LegendClass *b) { return a->id < b->id; });
    // as high as the image, or as the panel needs where the image is lower
    const Layout l(rows_);
    const int rows =
        std::max(rows_, Panel(Canvas(1, 1).cr(), l, annotations_, shown, cols_, rows_).needed_rows);
    const Panel panel(Canvas(1, 1).cr(), l, annotations_, std::move(shown), cols_, rows);

    // the panel drawn a strip of rows at a time, each moved up to its place
    // (a top view of 11,248 rows drawn whole took 110 MB beyond memory=)
    const int width = cols_ + panel.width;
    sbrt::PngFile png(path_, rows, width);
    std::vector<uint8_t> row(size_t(width) * 3, 255);
    const size_t image_row = size_t(cols_) * 3, side_row = size_t(panel.width) * 3;
    const int strip_rows = std::min(rows, PANEL_STRIP_ROWS);
    std::vector<uint8_t> side(size_t(strip_rows) * side_row);
    for (int top = 0; top < rows; top += strip_rows) {
        const int strip = std::min(strip_rows, rows - top);
        Canvas canvas(panel.width, strip_rows);
        cairo_translate(canvas.cr(), 0, -top);
        draw_panel(canvas.cr(), l, annotations_, panel, rows);
        canvas.store(side.data(), strip, panel.width);
        for (int r = top; r < top + strip; ++r) {
            if (r < rows_)
                std::copy_n(image_.data() + size_t(r) * image_row, image_row, row.data());
            else
                std::fill_n(row.data(), image_row, uint8_t(255));
            std::copy_n(side.data() + size_t(r - top) * side_row, side_row,
                        row.data() + image_row);
            png.write_rows(row.data(), 1);
        }
    }
    png.finish();
}
