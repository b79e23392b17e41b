/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The camera of each frame
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frame_cameras.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>

#include "scene/camera_path.hpp"
#include "scene_camera.hpp"
#include "vector_input.hpp"
#include "request_error.hpp"

namespace {

/// The whole of a text file (keys=). Where it cannot be read, throws the
/// request's error (bad_request): a GRASS error on the command line, the
/// view server's "error" reply.
std::string read_text_file(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
        bad_request(_("keys=%s: cannot read this file"), path.c_str());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

std::vector<sbrt::Camera> frame_cameras(const RenderRequest &request,
                                        const sbrt::Model &model,
                                        const sbrt::CoordinateFrame &frame,
                                        const struct Cell_head &region)
{
    const int frames = request.frames;
    if (request.path == sbrt::PathKind::sweep || (frames == 1 && request.path == sbrt::PathKind::orbit))
        return std::vector<sbrt::Camera>(size_t(frames),
                                         make_camera(request, model, frame, region));
    check_image_fits(request, request.height, request.width);
    if (request.path == sbrt::PathKind::orbit)
        return sbrt::orbit_cameras(request.view, model, frame, request.height, request.width,
                                   frames, request.angle);
    std::vector<sbrt::Camera> cameras;
    if (request.path == sbrt::PathKind::keys) {
        const std::vector<sbrt::Keyframe> keys =
            sbrt::parse_keyframes(read_text_file(request.keys), request.view.fov);
        for (int k = 1; k <= frames; ++k) {
            const sbrt::Keyframe key = sbrt::keyframe_at(keys, k, frames);
            sbrt::View view = request.view;
            view.position = key.position;
            view.target = key.target;
            view.fov = key.fov;
            cameras.push_back(
                sbrt::view_camera(view, model, frame, request.height, request.width));
        }
        return cameras;
    }
    // path=line: along the line, at its z or height= above the model
    bool is_3d = false;
    const std::vector<glm::dvec3> line = read_path_line(request.path_map, is_3d);
    if (!is_3d && !request.line_height)
        bad_request(_("path_map=%s is 2D: give height= (the camera's height "
                        "above the model's top)"),
                      request.path_map.c_str());
    const double length = sbrt::line_length(line);
    auto lifted = [&](glm::dvec3 p) {
        if (request.line_height)
            p.z = sbrt::surface_elevation(model, frame, p.x, p.y) + *request.line_height;
        return p;
    };
    for (int k = 1; k <= frames; ++k) {
        glm::dvec3 at, ahead;
        sbrt::along_line(line, k, frames, at, ahead);
        sbrt::View view = request.view;
        view.position = lifted(at);
        // looking ahead: with height= down at the model's top three heights
        // further on (some 18 degrees below the horizon); along a 3D line,
        // level, a frame's step further on
        if (!view.target && request.line_height) {
            const glm::dvec3 there = at + ahead * (3 * std::fabs(*request.line_height));
            view.target = glm::dvec3(there.x, there.y,
                                     sbrt::surface_elevation(model, frame, there.x, there.y));
        }
        else if (!view.target)
            view.target = *view.position + ahead * (length / std::max(1, frames - 1));
        cameras.push_back(sbrt::view_camera(view, model, frame, request.height, request.width));
    }
    return cameras;
}

