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
#include "scene/scene.hpp"
#include "vector_points.hpp"

/// \brief A borehole's collar: its category in layer= and its point.
using BoreholePoint = sbrt_grass::VectorPoint;

/// \brief One logged interval as the table gives it.
struct LogRow {
    double top = 0, bottom = 0;
    int class_id = 0;
};

/// \brief What boreholes= gives: the points of layer= that where=
/// selects (z given where the map is 3D), and with log_class= the rows of
/// log_top=, log_bottom=, log_class= in the layer's table grouped by
/// category (one row per interval; several per point).
struct BoreholeInput {
    std::vector<BoreholePoint> points;
    bool is_3d = false;
    std::map<int, std::vector<LogRow>> logs;
};

/// The boreholes of the request; throws (bad_request) where the map holds
/// no such points or the logs cannot be read.
BoreholeInput read_boreholes(const RenderRequest &request);

/// The vertices of the first line of `name` (z 0 where the map is 2D,
/// `is_3d` says which); throws (bad_request) without lines.
std::vector<glm::dvec3> read_path_line(const std::string &name, bool &is_3d);

/// The segments of the lines of fence=; throws (bad_request) without lines.
std::vector<sbrt::FencePanel> read_fence(const std::string &name);

#endif
