/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The output maps (and PNG file) of a render, written row by row
 *            as the renderer's bands arrive
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RASTER_OUTPUT_HPP
#define R3_SBRT_RASTER_OUTPUT_HPP

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "output/band.hpp"
#include "shading/property_paint.hpp"
#include "model/model.hpp"
#include "png_annotations.hpp"
#include "render_options.hpp"
#include "rgb_composite.hpp"

/// The raster window of a rows x cols image of a perspective or
/// orthographic view: square cells, as large as fit in `region`, centred
/// on it (the region itself is not changed).
struct Cell_head image_window(const struct Cell_head &region, int rows, int cols);

/// The cells of tile= (row, col, rows, cols) in the whole image's
/// `window`: the tiles' maps patch together.
struct Cell_head tile_window(struct Cell_head window, const std::array<int, 4> &tile);

/// The longer side a top view's PNG is enlarged to at least, without size=.
constexpr int MIN_TOP_VIEW_PNG_SIDE = 640;

/// How many pixels a side each pixel of the image (rows x cols) takes in
/// the PNG: 1 but for a top view, whose cells are enlarged by whole pixels
/// to fit size=, or without it to MIN_TOP_VIEW_PNG_SIDE on the longer side.
int png_enlargement(const RenderRequest &request, int rows, int cols);

/// \brief <output> (the image with exact colours), <output>.red/.green/.blue
/// and the optional maps of the request, open for writing in `window`
/// (rows x cols of the image), and the PNG. Maps appear only when close()
/// is reached (GRASS writes new maps aside).
class ImageMaps {
public:
    ImageMaps(const RenderRequest &request, const struct Cell_head &window,
              PngAnnotations annotations);
    ImageMaps(const ImageMaps &) = delete;
    ImageMaps &operator=(const ImageMaps &) = delete;

    /// The outputs a render must compute for these maps (and the legend).
    sbrt::Outputs outputs() const;
    /// The band's rows into every map (the bands in order, from the top).
    void write(const sbrt::Band &band);
    /// Closes the maps with their colours, categories (classes of `model`)
    /// and history; moves the PNG into place.
    void close(const sbrt::Model &model, const sbrt::PropertyPaint *property = nullptr);

private:
    struct Map {
        std::string name;
        int fd;
        RASTER_MAP_TYPE type;
    };
    Map open(const std::string &name, RASTER_MAP_TYPE type);

    const RenderRequest &request_;
    struct Cell_head window_; ///< the maps' (the output window)
    int cols_;
    std::unique_ptr<RgbComposite> composite_;
    std::vector<Map> rgb_;
    std::vector<Map> material_, elevation_, depth_, value_; ///< empty or one map
    std::vector<CELL> cells_;
    std::vector<DCELL> dcells_;
    std::unique_ptr<AnnotatedPng> png_;
};

#endif
