/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The profile's figure: the classes cut along the line, evenly
 *            coloured, with axes (elevation, distance along the line), the
 *            line's vertices, a legend of the classes cut, the vertical
 *            exaggeration and a location map with a north arrow (cairo)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROFILE_FIGURE_HPP
#define R3_SBRT_PROFILE_FIGURE_HPP

#include <optional>
#include <string>
#include <vector>

#include "cairo_canvas.hpp"
#include "model/model.hpp"
#include "measure/class_profile.hpp"
#include "measure/profile_line.hpp"

/// \brief Units of the axes' labels.
struct AxisUnits {
    std::string length = "m"; ///< of map units: "m", "ft", "map units"
    bool metres = true;       ///< distances of 5 km and more in km
    std::string datum;        ///< of elevations ("NAP"), empty where unknown
};

/// \brief The figure's axes: what the plot spans and where its ticks lie.
struct FigureAxes {
    double length = 0; ///< of the line (map units): the distance axis
    sbrt::ProfileExtent extent; ///< elevations, rounded out to ticks
    double zexag = 1;
    bool zexag_fitted = false;  ///< chosen from the line, not given
    int plot_width = 0, plot_height = 0; ///< pixels
    std::vector<double> elevation_ticks;
    std::vector<double> distance_ticks; ///< map units
    double distance_scale = 1; ///< map units per unit of the labels (1000: km)
    std::string distance_unit;

    /// Pixels below the plot's top edge of elevation `z`; right of its
    /// left edge of distance `d`: where ticks, labels and vertices go.
    double y_of(double z) const
    {
        return (extent.top - z) / (extent.top - extent.bottom) * plot_height;
    }
    double x_of(double d) const { return d / length * plot_width; }
};

/// The axes of a profile of a line `length` long through layers from
/// `solid`'s bottom to its top, `width` pixels wide; without `zexag` one
/// fitted to the line (the layers' thickness 0.3 of its length, rounded
/// as renders round theirs). Throws sbrt::Error where the plot would be
/// more than 8000 pixels high (a smaller zexag= or width= helps).
FigureAxes figure_axes(double length, sbrt::ProfileExtent solid, std::optional<double> zexag,
                       int width, const AxisUnits &units);

/// \brief Everything the figure shows beside its axes.
struct FigureContent {
    std::string title;
    /// The title where `title` is too wide for the figure (the line named
    /// by its first and last vertex); cut to the width where it is too.
    std::string short_title;
    const sbrt::Model *model = nullptr;        ///< cut and shown in the location map
    const sbrt::ProfileLine *line = nullptr;
    std::vector<sbrt_grass::LegendClass> classes; ///< every class, by material
    AxisUnits units;
};

/// \brief The figure laid out: its size and the plot's place in it.
struct FigureLayout {
    int width = 0, height = 0;
    int plot_left = 0, plot_top = 0;
    std::vector<int32_t> classes_cut; ///< ids, ascending
    /// The titles as drawn: fitted to the figure's width
    std::string title, distance_title;
    /// The vertices whose letters are drawn (on the plot's top edge and in
    /// the location map): every k-th where the letters of all would
    /// overlap, the first and the last always
    std::vector<size_t> lettered;
};

/// Lays the figure out and, where `png` is not empty, draws it into that
/// file (atomically). `profile` is the classes at the plot's pixels
/// (axes.plot_width x axes.plot_height over axes.extent).
FigureLayout draw_profile_figure(const FigureAxes &axes, const sbrt::ClassProfile &profile,
                                 const FigureContent &content, const std::string &png);

/// The map points whose columns the location map of a figure `plot_width`
/// wide shows (where the model has layers).
std::vector<glm::dvec2> location_samples(const sbrt::Frame &frame, const sbrt::ProfileLine &line,
                                         int plot_width);

/// The letter of vertex `k` (A, B, ..., Z, then A1, B1, ...).
std::string vertex_name(size_t k);

/// The axes' titles: "Elevation (m NAP)", "Distance along A\u2013B (km)".
std::string elevation_title(const AxisUnits &units);
std::string distance_title(const FigureAxes &axes, const std::string &line_name);

/// "A\u2013B\u2013C": the letters of a line of `vertices` vertices.
std::string line_name(size_t vertices);
/// "A\u2013\u2026\u2013H2": a line of `vertices` vertices by its first and
/// last (line_name where it has at most three).
std::string short_line_name(size_t vertices);

#endif
