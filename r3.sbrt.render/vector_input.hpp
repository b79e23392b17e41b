/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Reading the vector inputs: borehole points (layer=, where=),
 *            their logged intervals from the layer's table, fence lines
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_VECTOR_INPUT_HPP
#define R3_SBRT_VECTOR_INPUT_HPP

#include <map>
#include <string>
#include <vector>

#include "render_options.hpp"
#include "scene.hpp"

/// \brief A borehole's collar: its category in layer= and its point.
struct BoreholePoint {
    int cat = -1;
    double x = 0, y = 0, z = 0;
};

/// \brief One logged interval as the table gives it.
struct LogRow {
    double top = 0, bottom = 0;
    int class_id = 0;
};

/// The points of boreholes= in layer= that where= selects; a fatal error
/// where the map has no such points. `is_3d` tells whether z is given.
std::vector<BoreholePoint> read_borehole_points(const RenderRequest &request,
                                                bool &is_3d);

/// The rows of log_top=, log_bottom=, log_class= in the table of layer=,
/// grouped by category (one row per interval; several per point).
std::map<int, std::vector<LogRow>> read_borehole_logs(const RenderRequest &request);

/// The segments of the lines of fence=; a fatal error without lines.
std::vector<sbrt::FencePanel> read_fence(const std::string &name);

#endif
