/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Sequences of views: orbit and sweep
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "scene/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include <glm/geometric.hpp>

#include "util/error.hpp"

namespace sbrt {

PathKind parse_path_kind(const std::string &word)
{
    for (PathKind kind : {PathKind::orbit, PathKind::line, PathKind::keys, PathKind::sweep})
        if (word == path_kind_name(kind))
            return kind;
    fail("path: '", word, "' is none of orbit, line, keys, sweep");
}

const char *path_kind_name(PathKind kind)
{
    switch (kind) {
    case PathKind::orbit: return "orbit";
    case PathKind::line: return "line";
    case PathKind::keys: return "keys";
    case PathKind::sweep: return "sweep";
    }
    return "?";
}

glm::dvec3 turn_about_vertical(glm::dvec3 p, glm::dvec3 axis, double degrees)
{
    const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
    const glm::dvec2 d(p.x - axis.x, p.y - axis.y);
    return {axis.x + c * d.x - s * d.y, axis.y + s * d.x + c * d.y, p.z};
}

std::vector<Camera> orbit_cameras(const View &view, const Model &model,
                                  const CoordinateFrame &frame, int rows,
                                  int cols, int frames, double angle)
{
    if (frames < 1)
        fail("orbit: ", frames, " frames; at least one");
    if (view.kind == ViewKind::top)
        fail("orbit: a top view does not turn (view=perspective or orthographic)");
    const std::vector<glm::dvec3> hull = framing_hull(model, frame);
    const glm::dvec3 target =
        view.target ? frame.exaggerated_from_map(*view.target) : frame.centre();
    auto turn = [&](int k) { return (k - 1) * angle / frames; };
    // the direction from the target to the camera in frame 1
    glm::dvec3 offset;
    if (view.position) {
        offset = frame.exaggerated_from_map(*view.position) - target;
        if (!(glm::length(offset) > 0))
            fail("orbit: position= and target= are the same point");
    }
    else {
        const double az = view.azimuth * M_PI / 180, el = view.elevation * M_PI / 180;
        offset = {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
    }
    const glm::dvec3 unit = glm::normalize(offset);
    const double aspect = double(cols) / rows;
    std::vector<Camera> cameras;
    if (view.kind == ViewKind::orthographic) {
        double height = view.ortho_height.value_or(0);
        if (!view.ortho_height) {
            // the largest extent about the target over all frames
            for (int k = 1; k <= frames; ++k) {
                const glm::dvec3 forward = -turn_about_vertical(unit, {0, 0, 0}, turn(k));
                glm::dvec3 right, up;
                view_basis(forward, right, up);
                right = glm::normalize(right);
                up = glm::normalize(up);
                for (const glm::dvec3 &p : hull) {
                    const glm::dvec3 v = p - target;
                    height = std::max({height, 2 * std::fabs(glm::dot(v, up)),
                                       2 * std::fabs(glm::dot(v, right)) / aspect});
                }
            }
            height /= 0.95;
        }
        for (int k = 1; k <= frames; ++k) {
            const glm::dvec3 u = turn_about_vertical(unit, {0, 0, 0}, turn(k));
            cameras.push_back(Camera::orthographic(orthographic_start(frame, target, u),
                                                   target, height, rows, cols));
        }
        return cameras;
    }
    // frame 1's position: position= as given (each frame then is exactly
    // the single view from the turned position), else at the distance
    glm::dvec3 first = target + offset;
    if (!view.position) {
        double distance = view.distance.value_or(0);
        if (!view.distance)
            for (int k = 1; k <= frames; ++k)
                distance = std::max(
                    distance, framing_distance(hull, target,
                                               turn_about_vertical(unit, {0, 0, 0}, turn(k)),
                                               view.fov, aspect));
        first = target + unit * distance;
    }
    else {
        first = frame.exaggerated_from_map(*view.position);
    }
    for (int k = 1; k <= frames; ++k)
        cameras.push_back(Camera::perspective(turn_about_vertical(first, target, turn(k)),
                                              target, view.fov, rows, cols));
    return cameras;
}

std::vector<Keyframe> parse_keyframes(const std::string &text, double fov)
{
    std::vector<Keyframe> keys;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        std::vector<double> v;
        std::string field;
        while (fields >> field) {
            char *end = nullptr;
            const double x = std::strtod(field.c_str(), &end);
            if (*end || !std::isfinite(x))
                fail("keyframes, line ", number, ": <", field, "> is not a number");
            v.push_back(x);
        }
        if (v.empty())
            continue;
        if (v.size() != 6 && v.size() != 7)
            fail("keyframes, line ", number, ": ", v.size(),
                 " numbers; give x y z tx ty tz [fov]");
        Keyframe k{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v.size() == 7 ? v[6] : fov};
        if (k.position == k.target)
            fail("keyframes, line ", number, ": the position is the target");
        if (!(k.fov > 0 && k.fov < 180))
            fail("keyframes, line ", number, ": fov ", k.fov, " is not within 0-180");
        keys.push_back(k);
    }
    if (keys.size() < 2)
        fail("keyframes: ", keys.size(), " keyframe", keys.size() == 1 ? "" : "s",
             "; a path needs at least two");
    return keys;
}

namespace {

/// Catmull-Rom through p1 (t = 0) and p2 (t = 1), neighbours p0 and p3.
glm::dvec3 catmull_rom(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 p3, double t)
{
    const double t2 = t * t, t3 = t2 * t;
    return 0.5 * (2.0 * p1 + (p2 - p0) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2 +
                  (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3);
}

} // namespace

Keyframe keyframe_at(const std::vector<Keyframe> &keys, int frame, int frames)
{
    if (keys.size() < 2 || frames < 1 || frame < 1 || frame > frames)
        fail("keyframe_at: frame ", frame, " of ", frames, " through ", keys.size(),
             " keys");
    const double u = frames == 1 ? 0 : double(frame - 1) / (frames - 1) * (keys.size() - 1);
    const size_t i = std::min(size_t(u), keys.size() - 2);
    const double t = u - double(i);
    // the ends repeat their key: the curve starts and ends at them
    const Keyframe &k0 = keys[i == 0 ? 0 : i - 1], &k1 = keys[i], &k2 = keys[i + 1],
                   &k3 = keys[std::min(i + 2, keys.size() - 1)];
    Keyframe k;
    k.position = catmull_rom(k0.position, k1.position, k2.position, k3.position, t);
    k.target = catmull_rom(k0.target, k1.target, k2.target, k3.target, t);
    k.fov = k1.fov + (k2.fov - k1.fov) * t;
    return k;
}

double line_length(const std::vector<glm::dvec3> &line)
{
    double length = 0;
    for (size_t i = 1; i < line.size(); ++i)
        length += glm::length(glm::dvec2(line[i] - line[i - 1]));
    return length;
}

void along_line(const std::vector<glm::dvec3> &line, int frame, int frames,
                glm::dvec3 &point, glm::dvec3 &direction)
{
    if (frames < 1 || frame < 1 || frame > frames)
        fail("along_line: frame ", frame, " of ", frames);
    const double length = line_length(line);
    if (!(length > 0))
        fail("path line: it has no length (fewer than two distinct points)");
    double s = frames == 1 ? 0 : length * (frame - 1) / (frames - 1);
    for (size_t i = 1; i < line.size(); ++i) {
        const glm::dvec3 a = line[i - 1], b = line[i];
        const double piece = glm::length(glm::dvec2(b - a));
        if (piece == 0)
            continue;
        if (s <= piece || i + 1 == line.size()) {
            const double t = std::min(1.0, s / piece);
            point = a + (b - a) * t;
            direction = glm::normalize(glm::dvec3(glm::dvec2(b - a), 0.0));
            return;
        }
        s -= piece;
    }
}

double surface_elevation(const Model &model, const CoordinateFrame &frame, double x,
                         double y)
{
    const Frame &f = model.frame();
    const double col = std::floor((x - f.west) / f.ew_res());
    const double row = std::floor((f.north - y) / f.ns_res());
    if (col >= 0 && row >= 0 && col < f.cols && row < f.rows) {
        const double top = model.stack_top(model.cell_index(int(row), int(col)));
        if (top >= 0)
            return frame.map_from_local({0, 0, top}).z;
    }
    return frame.top_elevation();
}

ClipPlane swept_plane(const ClipPlane &plane, const CoordinateFrame &box, int frame, int frames)
{
    if (frames < 1 || frame < 1 || frame > frames)
        fail("sweep: frame ", frame, " of ", frames);
    const double length = glm::length(plane.normal);
    if (!(length > 0))
        fail("sweep: the plane's normal is zero");
    const glm::dvec3 n = plane.normal / length;
    // the box's extent along the normal (real map coordinates)
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (int k = 0; k < 8; ++k) {
        const double t = glm::dot(box.map_from_exaggerated(box.corner(k)), n);
        low = std::min(low, t);
        high = std::max(high, t);
    }
    const double at = high - (high - low) * (frame - 1) / frames;
    const glm::dvec3 point = plane.point + (at - glm::dot(plane.point, n)) * n;
    return {point, plane.normal};
}

} // namespace sbrt
