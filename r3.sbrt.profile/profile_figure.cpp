/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The profile's figure, drawn with cairo
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "profile_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "frame/fitting_exaggeration.hpp"
#include "output/png_file.hpp"
#include "grass.hpp"
#include "module_errors.hpp"
#include "util/axis_ticks.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

using sbrt_grass::Canvas;
using sbrt_grass::LegendClass;
using sbrt_grass::select_font;
using sbrt_grass::show_text;
using sbrt_grass::text_extents;
using sbrt_grass::text_width;

namespace {

/// Highest plot a figure may have, in pixels.
constexpr int MAX_PLOT_HEIGHT = 8000;
/// Most samples a side of the location map's footprint.
constexpr int MAX_LOCATION_SAMPLES = 24;

std::string number_text(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", std::abs(value) < 1e-9 ? 0.0 : value);
    return text;
}

/// Sizes in pixels for a plot `width` wide: a 13-pixel font at 1000.
struct Sizes {
    explicit Sizes(int width)
        : scale(std::clamp(width / 1000.0, 1.0, 3.0)), font(13 * scale), line(1.5 * font),
          pad(8 * scale), tick(5 * scale), inset(190 * scale), arrow(34 * scale)
    {
    }
    double scale, font, line, pad, tick, inset, arrow;
};

/// Where the parts go, measured with the figure's font.
struct Placement {
    Placement(cairo_t *cr, const Sizes &s, const FigureAxes &a,
              std::vector<const LegendClass *> shown)
        : shown(std::move(shown))
    {
        cairo_set_font_size(cr, s.font);
        double labels = 0;
        for (double t : a.elevation_ticks)
            labels = std::max(labels, text_width(cr, number_text(t)));
        left = int(std::ceil(s.pad + s.font + s.pad + labels + s.pad + s.tick));
        top = int(std::ceil(s.pad + 2 * s.line + s.pad));
        const double bottom = s.tick + s.pad + 2 * s.line + s.pad;
        zexag_text = exaggeration_text(a);
        double panel = std::max({s.inset + s.pad + s.arrow, text_width(cr, zexag_text)});
        for (const LegendClass *l : this->shown)
            panel = std::max(panel, s.font + s.pad + text_width(cr, sbrt_grass::legend_text(*l)));
        select_font(cr, true);
        panel = std::max(panel, text_width(cr, "Classes cut"));
        select_font(cr);
        panel_left = left + a.plot_width + int(std::ceil(3 * s.pad));
        width = panel_left + int(std::ceil(panel + 2 * s.pad));
        const double panel_height = s.pad + s.line * double(this->shown.size() + 2) +
                                    s.line + s.pad + s.line + s.inset + 2 * s.pad;
        height = int(std::ceil(std::max(top + a.plot_height + bottom, top + panel_height)));
    }
    static std::string exaggeration_text(const FigureAxes &a)
    {
        char text[64];
        std::snprintf(text, sizeof text, "Vertical exaggeration %g\u00d7", a.zexag);
        return text;
    }
    std::vector<const LegendClass *> shown;
    std::string zexag_text;
    int left = 0, top = 0, panel_left = 0, width = 0, height = 0;
};

/// The plot's pixels: each its class's colour, white where nothing is.
void fill_plot(Canvas &canvas, const Placement &p, const sbrt::ClassProfile &profile,
               const std::unordered_map<int32_t, std::array<uint8_t, 3>> &colors)
{
    cairo_surface_flush(cairo_get_target(canvas.cr()));
    for (int r = 0; r < profile.rows; ++r) {
        uint32_t *px = canvas.row(p.top + r) + p.left;
        for (int c = 0; c < profile.cols; ++c) {
            const int32_t id = profile.at(r, c);
            const auto found = colors.find(id);
            if (found == colors.end())
                continue;
            const auto &rgb = found->second;
            px[c] = 0xff000000u | uint32_t(rgb[0]) << 16 | uint32_t(rgb[1]) << 8 | rgb[2];
        }
    }
    canvas.mark_dirty();
}

void show_text_at(cairo_t *cr, const std::string &text, double x, double y, double align_x,
                  double align_y)
{
    const cairo_text_extents_t e = text_extents(cr, text);
    cairo_move_to(cr, x - align_x * e.x_advance, y - e.y_bearing - align_y * e.height);
    show_text(cr, text);
}

/// `text` at the current font cut to at most `width` pixels on a
/// character boundary, ending in an ellipsis where it was cut (nothing
/// where not even that fits).
std::string fit_text(cairo_t *cr, const std::string &text, double width)
{
    const std::string valid = sbrt::valid_utf8(text);
    if (text_width(cr, valid) <= width)
        return valid;
    const std::string ellipsis = "\u2026";
    // the ends of its characters; the longest prefix that fits, by halves
    std::vector<size_t> ends{0};
    for (size_t i = 1; i < valid.size(); ++i)
        if ((static_cast<unsigned char>(valid[i]) & 0xc0) != 0x80)
            ends.push_back(i);
    size_t low = 0, high = ends.size() - 1; // ends[low] fits, ends[high + 1] not
    if (text_width(cr, ellipsis) > width)
        return "";
    while (low < high) {
        const size_t mid = (low + high + 1) / 2;
        if (text_width(cr, valid.substr(0, ends[mid]) + ellipsis) <= width)
            low = mid;
        else
            high = mid - 1;
    }
    return valid.substr(0, ends[low]) + ellipsis;
}

/// \brief Where a letter is drawn, in image pixels.
struct LetterBox {
    double x0, y0, x1, y1;
};

/// Whether `a` and `b` are at least `gap` pixels apart.
bool apart(const LetterBox &a, const LetterBox &b, double gap)
{
    return a.x1 + gap <= b.x0 || b.x1 + gap <= a.x0 || a.y1 + gap <= b.y0 ||
           b.y1 + gap <= a.y0;
}

/// Whether the letters `chosen` of each set of boxes are apart by `gap`.
bool letters_apart(const std::vector<size_t> &chosen,
                   const std::vector<const std::vector<LetterBox> *> &sets, double gap)
{
    for (const std::vector<LetterBox> *boxes : sets)
        for (size_t i = 0; i < chosen.size(); ++i)
            for (size_t j = i + 1; j < chosen.size(); ++j)
                if (!apart((*boxes)[chosen[i]], (*boxes)[chosen[j]], gap))
                    return false;
    return true;
}

/// The vertices to letter: every k-th with the least k at which the
/// letters of each set of boxes lie apart, the last always (the k-th
/// before it left out where the two would touch); the first and the last
/// alone where no k lets more fit.
std::vector<size_t> lettered_vertices(const std::vector<const std::vector<LetterBox> *> &sets,
                                      size_t n, double gap)
{
    if (n <= 2) {
        std::vector<size_t> all;
        for (size_t k = 0; k < n; ++k)
            all.push_back(k);
        return all;
    }
    for (size_t k = 1; k + 1 < n; ++k) {
        std::vector<size_t> chosen;
        for (size_t v = 0; v + 1 < n; v += k)
            chosen.push_back(v);
        if (chosen.size() > 1 &&
            !letters_apart({chosen.back(), n - 1}, sets, gap))
            chosen.pop_back();
        chosen.push_back(n - 1);
        if (letters_apart(chosen, sets, gap))
            return chosen;
    }
    return {0, n - 1};
}

/// The frame, ticks and their labels, the axes' titles, the vertices
/// (`layout`'s letters and titles).
void draw_axes(cairo_t *cr, const Sizes &s, const Placement &p, const FigureAxes &a,
               const FigureContent &c, const FigureLayout &layout)
{
    const double x0 = p.left, y0 = p.top, w = a.plot_width, h = a.plot_height;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, x0 - 0.5, y0 - 0.5, w + 1, h + 1);
    cairo_stroke(cr);
    for (double t : a.elevation_ticks) {
        const double y = std::round(y0 + a.y_of(t)) + 0.5;
        cairo_move_to(cr, x0 - 0.5, y);
        cairo_line_to(cr, x0 - 0.5 - s.tick, y);
        cairo_stroke(cr);
        show_text_at(cr, number_text(t), x0 - s.tick - s.pad / 2, y, 1, 0.5);
    }
    for (double t : a.distance_ticks) {
        const double x = std::round(x0 + a.x_of(t)) + 0.5;
        cairo_move_to(cr, x, y0 + h + 0.5);
        cairo_line_to(cr, x, y0 + h + 0.5 + s.tick);
        cairo_stroke(cr);
        show_text_at(cr, number_text(t / a.distance_scale), x, y0 + h + s.tick + s.pad / 2, 0.5,
                     0);
    }
    show_text_at(cr, layout.distance_title, x0 + w / 2, y0 + h + s.tick + s.pad / 2 + s.line,
                 0.5, 0);
    // the elevation's title, turned to read upwards, cut to the figure's
    // height about the plot's middle
    const double centre = y0 + h / 2;
    const double room = 2 * std::min(centre, p.height - centre) - 2 * s.pad;
    cairo_save(cr);
    cairo_translate(cr, s.pad, centre);
    cairo_rotate(cr, -M_PI / 2);
    show_text_at(cr, fit_text(cr, elevation_title(c.units), room), 0, 0, 0.5, 0);
    cairo_restore(cr);

    // vertices: letters above the plot where they fit, a short tick
    // above it at every vertex, bends of lettered vertices as dashed lines
    // through it
    const auto &distances = c.line->vertex_distances();
    std::vector<bool> lettered(distances.size());
    for (size_t k : layout.lettered)
        lettered[k] = true;
    select_font(cr, true);
    for (size_t k = 0; k < distances.size(); ++k) {
        const double x = std::round(x0 + a.x_of(distances[k])) + 0.5;
        if (!lettered[k]) {
            cairo_move_to(cr, x, y0 - 0.5);
            cairo_line_to(cr, x, y0 - 0.5 - s.tick);
            cairo_stroke(cr);
            continue;
        }
        // on one baseline (a J's descender below it), as high as an A
        cairo_move_to(cr, x - text_width(cr, vertex_name(k)) / 2, y0 - s.pad / 2);
        show_text(cr, vertex_name(k));
        if (k == 0 || k + 1 == distances.size())
            continue;
        const double dash = 4 * s.scale;
        cairo_set_dash(cr, &dash, 1, 0);
        cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
        cairo_move_to(cr, x, y0);
        cairo_line_to(cr, x, y0 + h);
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        cairo_set_source_rgb(cr, 0, 0, 0);
    }
    // the title above the letters
    show_text_at(cr, layout.title, x0, s.pad, 0, 0);
    select_font(cr);
}

/// \brief The location map's frame: an area holding the model and the
/// line, `side` pixels on its longer side; the cells with layers are
/// sampled on a grid of at most MAX_LOCATION_SAMPLES a side (each sample
/// decodes the block holding it: a finer grid would read a national
/// model's every block for a picture 190 pixels wide).
struct LocationFrame {
    LocationFrame(const sbrt::Frame &f, const sbrt::ProfileLine &line, double side, double scale_px)
        : west(f.west), east(f.east), south(f.south), north(f.north), model(f)
    {
        for (const glm::dvec2 &v : line.vertices()) {
            west = std::min(west, v.x);
            east = std::max(east, v.x);
            south = std::min(south, v.y);
            north = std::max(north, v.y);
        }
        const double margin = 0.04 * std::max(east - west, north - south);
        west -= margin, east += margin, south -= margin, north += margin;
        scale = side / std::max(east - west, north - south);
        w = (east - west) * scale;
        h = (north - south) * scale;
        across = std::clamp(int(std::ceil((f.east - f.west) * scale / (3 * scale_px))), 1,
                            MAX_LOCATION_SAMPLES);
        down = std::clamp(int(std::ceil((f.north - f.south) * scale / (3 * scale_px))), 1,
                          MAX_LOCATION_SAMPLES);
    }
    /// Map corner of sample (r, k): its north-west for (r, k), ...
    glm::dvec2 corner(int r, int k) const
    {
        return {model.west + k * (model.east - model.west) / across,
                model.north - r * (model.north - model.south) / down};
    }
    glm::dvec2 sample(int r, int k) const
    {
        return 0.5 * (corner(r, k) + corner(r + 1, k + 1));
    }
    double west, east, south, north, scale = 1, w = 0, h = 0;
    int across = 1, down = 1;
    sbrt::Frame model;
};

/// Where the location map at (x, y) puts the letter of each vertex (the
/// bold font at the figure's size selected): up and right of it, kept
/// inside the map.
std::vector<LetterBox> location_letters(cairo_t *cr, const Sizes &s, const FigureContent &c,
                                        double x, double y)
{
    const LocationFrame l(c.model->frame(), *c.line, s.inset, s.scale);
    std::vector<LetterBox> boxes;
    for (size_t k = 0; k < c.line->vertices().size(); ++k) {
        const glm::dvec2 v = c.line->vertices()[k];
        const double px = x + (v.x - l.west) * l.scale, py = y + (l.north - v.y) * l.scale;
        const double left = std::clamp(px + 0.3 * s.font, x, x + l.w - s.font);
        const double top = std::clamp(py - 1.2 * s.font, y, y + l.h - s.font);
        const cairo_text_extents_t e = text_extents(cr, vertex_name(k));
        boxes.push_back({left, top, left + e.x_advance, top + e.height});
    }
    return boxes;
}

/// The model's outline and the cells with layers (grey) over an area
/// holding the model and the line, the line in red with the letters of
/// the vertices `lettered`; a north arrow beside it.
void draw_location(cairo_t *cr, const Sizes &s, const FigureContent &c, double x, double y,
                   const std::vector<size_t> &lettered)
{
    const sbrt::Frame &f = c.model->frame();
    const LocationFrame l(f, *c.line, s.inset, s.scale);
    const double w = l.w, h = l.h;
    const auto at = [&](glm::dvec2 m) {
        return glm::dvec2(x + (m.x - l.west) * l.scale, y + (l.north - m.y) * l.scale);
    };
    cairo_save(cr);
    cairo_rectangle(cr, x, y, w, h);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.8, 0.8, 0.8);
    for (int r = 0; r < l.down; ++r)
        for (int k = 0; k < l.across; ++k) {
            const glm::dvec2 m = l.sample(r, k);
            const auto cell = sbrt::cell_of_point(f, m.x, m.y);
            if (!cell || c.model->stack_top(c.model->cell_index(cell->row, cell->col)) < 0)
                continue;
            const glm::dvec2 a = at(l.corner(r, k)), b = at(l.corner(r + 1, k + 1));
            cairo_rectangle(cr, std::floor(a.x), std::floor(a.y), std::ceil(b.x) - std::floor(a.x),
                            std::ceil(b.y) - std::floor(a.y));
        }
    cairo_fill(cr);
    const glm::dvec2 nw = at({f.west, f.north}), se = at({f.east, f.south});
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, nw.x, nw.y, se.x - nw.x, se.y - nw.y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.85, 0.05, 0.05);
    cairo_set_line_width(cr, 2 * s.scale);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (const glm::dvec2 &v : c.line->vertices()) {
        const glm::dvec2 p = at(v);
        cairo_line_to(cr, p.x, p.y);
    }
    cairo_stroke(cr);
    cairo_restore(cr);
    select_font(cr, true);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::vector<LetterBox> boxes = location_letters(cr, s, c, x, y);
    for (size_t k : lettered)
        show_text_at(cr, vertex_name(k), boxes[k].x0, boxes[k].y0, 0, 0);
    select_font(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, x + 0.5, y + 0.5, w - 1, h - 1);
    cairo_stroke(cr);
    sbrt_grass::draw_north_arrow(cr, {0, -1}, {x + w + s.pad + s.arrow / 2, y + s.font + s.arrow / 2},
                                 s.arrow, s.font, s.scale);
}

/// The titles fitted to the figure (the title from the plot's left edge
/// to the figure's right one, the distance's to the plot's width: the
/// location map may lie beside it) and the vertices to letter, measured
/// at the figure's fonts.
void lay_out_text(cairo_t *cr, const Sizes &s, const Placement &p, const FigureAxes &a,
                  const FigureContent &c, double inset_top, FigureLayout &layout)
{
    cairo_set_font_size(cr, s.font);
    select_font(cr, true);
    const double title_room = p.width - p.left - s.pad;
    layout.title = text_width(cr, c.title) <= title_room || c.short_title.empty()
                       ? fit_text(cr, c.title, title_room)
                       : fit_text(cr, c.short_title, title_room);
    // the vertices' letters: on the plot's top edge, centred on each
    // vertex, and in the location map
    const size_t n = c.line->vertices().size();
    std::vector<LetterBox> top;
    for (size_t k = 0; k < n; ++k) {
        const double x = std::round(p.left + a.x_of(c.line->vertex_distances()[k])) + 0.5;
        const double half = text_width(cr, vertex_name(k)) / 2;
        top.push_back({x - half, 0, x + half, s.font});
    }
    const std::vector<LetterBox> map = location_letters(cr, s, c, p.panel_left, inset_top);
    layout.lettered = lettered_vertices({&top, &map}, n, 0.4 * s.font);
    select_font(cr);
    const double distance_room = a.plot_width;
    const std::string full = distance_title(a, line_name(n));
    layout.distance_title =
        text_width(cr, full) <= distance_room
            ? full
            : fit_text(cr, distance_title(a, short_line_name(n)), distance_room);
}

void draw_panel(cairo_t *cr, const Sizes &s, const Placement &p)
{
    const double x = p.panel_left;
    double y = p.top + s.line - 0.3 * s.font;
    select_font(cr, true);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x, y);
    show_text(cr, "Classes cut");
    select_font(cr);
    for (const LegendClass *l : p.shown) {
        y += s.line;
        sbrt_grass::draw_legend_entry(cr, *l, x, y, s.font, s.pad);
    }
    y += 2 * s.line;
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, x, y);
    show_text(cr, p.zexag_text);
}

} // namespace

std::vector<glm::dvec2> location_samples(const sbrt::Frame &frame, const sbrt::ProfileLine &line,
                                         int plot_width)
{
    const Sizes s(plot_width);
    const LocationFrame l(frame, line, s.inset, s.scale);
    std::vector<glm::dvec2> points;
    for (int r = 0; r < l.down; ++r)
        for (int k = 0; k < l.across; ++k)
            points.push_back(l.sample(r, k));
    return points;
}

std::string elevation_title(const AxisUnits &u)
{
    return "Elevation (" + u.length + (u.datum.empty() ? "" : " " + u.datum) + ")";
}

std::string distance_title(const FigureAxes &a, const std::string &line_name)
{
    return "Distance along " + line_name + " (" + a.distance_unit + ")";
}

std::string line_name(size_t vertices)
{
    std::string name;
    for (size_t k = 0; k < vertices; ++k)
        name += (k ? "\u2013" : "") + vertex_name(k);
    return name;
}

std::string short_line_name(size_t vertices)
{
    if (vertices <= 3)
        return line_name(vertices);
    return vertex_name(0) + "\u2013\u2026\u2013" + vertex_name(vertices - 1);
}

std::string vertex_name(size_t k)
{
    std::string name(1, char('A' + k % 26));
    if (k >= 26)
        name += std::to_string(k / 26);
    return name;
}

FigureAxes figure_axes(double length, sbrt::ProfileExtent solid, std::optional<double> zexag,
                       int width, const AxisUnits &units)
{
    FigureAxes a;
    a.length = length;
    a.plot_width = width;
    a.zexag_fitted = !zexag;
    a.zexag = zexag ? *zexag
                    : sbrt::fitting_exaggeration(length, length, solid.top - solid.bottom);
    // elevations rounded out to ticks at least 40 pixels apart
    const double rough = (solid.top - solid.bottom) * a.zexag * width / length;
    const int most = std::clamp(int(rough / 40), 2, 10);
    const double step = sbrt::tick_step(solid.bottom, solid.top, most);
    a.extent = {std::floor(solid.bottom / step) * step, std::ceil(solid.top / step) * step};
    const double height = (a.extent.top - a.extent.bottom) * a.zexag * width / length;
    if (height > MAX_PLOT_HEIGHT)
        sbrt_grass::fail_with(
            _("The profile would be %ld pixels high (more than %d) at vertical "
              "exaggeration %g: give a smaller zexag= or width="),
            std::lround(height), MAX_PLOT_HEIGHT, a.zexag);
    a.plot_height = std::max(1, int(std::lround(height)));
    a.elevation_ticks = sbrt::ticks(a.extent.bottom, a.extent.top, step);

    a.distance_unit = units.length;
    if (units.metres && length >= 5000) {
        a.distance_scale = 1000;
        a.distance_unit = "km";
    }
    const double labels = length / a.distance_scale;
    const double distance_step =
        sbrt::tick_step(0, labels, std::clamp(width / 110, 2, 12)) * a.distance_scale;
    a.distance_ticks = sbrt::ticks(0, length, distance_step);
    return a;
}

FigureLayout draw_profile_figure(const FigureAxes &axes, const sbrt::ClassProfile &profile,
                                 const FigureContent &content, const std::string &png)
{
    // the classes at the plot's pixels (main.cpp asks for them so)
    SBRT_CHECK_EQ(profile.cols, axes.plot_width, "draw_profile_figure");
    SBRT_CHECK_EQ(profile.rows, axes.plot_height, "draw_profile_figure");
    // the classes cut, ascending
    std::unordered_map<int32_t, std::array<uint8_t, 3>> colors;
    std::unordered_map<int32_t, const LegendClass *> legend;
    for (const LegendClass &l : content.classes) {
        colors.emplace(l.id, l.color);
        legend.emplace(l.id, &l);
    }
    FigureLayout layout;
    std::vector<bool> seen;
    {
        std::vector<int32_t> ids = profile.classes;
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        for (int32_t id : ids)
            if (id != sbrt::NULL_CLASS)
                layout.classes_cut.push_back(id);
    }
    std::vector<const LegendClass *> shown;
    for (int32_t id : layout.classes_cut)
        if (const auto found = legend.find(id); found != legend.end())
            shown.push_back(found->second);

    const Sizes s(axes.plot_width);
    Canvas measure(1, 1);
    cairo_t *m = measure.cr();
    const Placement p(m, s, axes, shown);
    layout.width = p.width;
    layout.height = p.height;
    layout.plot_left = p.left;
    layout.plot_top = p.top;
    const double inset_top = p.top + s.line * double(shown.size() + 3) + s.pad;
    lay_out_text(m, s, p, axes, content, inset_top, layout);
    if (png.empty())
        return layout;

    sbrt::PngFile file(png, p.height, p.width); // fails before drawing where it cannot
    Canvas canvas(p.width, p.height);
    cairo_t *cr = canvas.cr();
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    fill_plot(canvas, p, profile, colors);
    cairo_set_font_size(cr, s.font);
    draw_axes(cr, s, p, axes, content, layout);
    draw_panel(cr, s, p);
    draw_location(cr, s, content, p.panel_left, inset_top, layout.lettered);
    std::vector<uint8_t> rgb(size_t(p.width) * size_t(p.height) * 3);
    canvas.store(rgb.data(), p.height, p.width);
    file.write_rows(rgb.data(), p.height);
    file.finish();
    return layout;
}
