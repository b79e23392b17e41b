/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The PNG of a render with what a reader needs to read it alone:
 *            a legend of the classes seen, a north arrow, the vertical
 *            exaggeration, on top views a scale bar (drawn with cairo)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PNG_ANNOTATIONS_HPP
#define R3_SBRT_PNG_ANNOTATIONS_HPP

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "cairo_canvas.hpp"
#include "output/band.hpp"
#include "output/png_file.hpp"

using sbrt_grass::LegendClass;

/// \brief The legend of a property view: a colour bar.
struct ColorBar {
    std::string name, long_name, unit; ///< of the property shown
    double low = 0, high = 1;          ///< the bar's ends
    /// colours from low to high, evenly spaced (the bar's pixels sample it)
    std::vector<std::array<uint8_t, 3>> colors;
    std::array<uint8_t, 3> no_value{190, 190, 190};
};

/// \brief What the PNG is annotated with; all empty: a plain image.
struct PngAnnotations {
    std::string title;                 ///< heads the legend (the SBRT's name)
    std::vector<LegendClass> classes;  ///< those the image can show, in order
    std::optional<ColorBar> bar;       ///< a property view's legend, instead
    std::string caption;               ///< a line below the legend (select=, fade=)
    std::optional<glm::dvec2> north;   ///< image direction (x right, y down)
    std::optional<double> zexag;       ///< shown for 3D views
    std::optional<double> metres_per_pixel; ///< top views: a scale bar
    bool scale_in_metres = true; ///< false: map units of an XY location
    bool empty() const
    {
        return classes.empty() && !bar && !north && !zexag && !metres_per_pixel;
    }
};

/// \brief The PNG of an image, each pixel drawn `enlarge` x `enlarge`
/// (a top view of few cells). Plain, its rows stream into the file as
/// they come. Annotated, the file is the image with a panel on its right:
/// the legend of the classes the image shows (known once every band has
/// been seen, so the image is held: 3 bytes a pixel), below it the north
/// arrow, the vertical exaggeration and the scale bar; written by
/// finish(). Text is never smaller than a 480-row image's: where the image
/// is lower than the panel needs, the file is as high as the panel, white
/// below the image. Bands must carry their class ids when needs_classes().
class AnnotatedPng {
public:
    AnnotatedPng(const std::string &path, int rows, int cols,
                 PngAnnotations annotations, int enlarge = 1);

    void write(const sbrt::Band &band);
    void finish();
    bool needs_classes() const { return !annotations_.classes.empty(); }
    bool annotated() const { return !annotations_.empty(); }

private:
    void count_classes(const sbrt::Band &band);

    /// The band's rows, each pixel `enlarge_` times, `enlarge_` times.
    void write_enlarged(const sbrt::Band &band);

    std::string path_;
    int rows_, cols_, enlarge_;
    PngAnnotations annotations_;
    std::optional<sbrt::PngFile> png_; ///< plain: open from the start
    std::vector<uint8_t> row_;         ///< plain: one enlarged row
    std::vector<uint8_t> image_;       ///< annotated: the whole image, enlarged
    std::unordered_map<int32_t, size_t> class_index_;
    std::vector<bool> seen_; ///< per annotations_.classes
};

#endif
