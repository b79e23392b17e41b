/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Options of the module and their validation
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_RENDER_OPTIONS_HPP
#define R3_SBRT_RENDER_OPTIONS_HPP

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "grass.hpp"
#include "shading/shading.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene_parts.hpp"
#include "scene/view.hpp"

/// \brief Everything the user asked for, validated, map units.
struct RenderRequest {
    std::string input, output, material, hit_elevation, depth, png;
    std::string value;                       ///< value=: the property at the hit
    std::vector<std::string> property;       ///< channels to show, summed
    std::string property_color = "viridis";  ///< colour table or rules file
    std::string select;                      ///< select=: a condition on channels
    std::string fade;                        ///< fade=: an uncertainty channel
    std::optional<std::array<double, 2>> fade_range; ///< its values of no and full grey
    bool annotate = true;  ///< the PNG's legend, north arrow, scale bar (not -n)
    std::optional<std::array<int, 4>> tile; ///< row, col, rows, cols of the image
    int width = 640, height = 480; ///< size=: perspective and orthographic
    bool size_given = false;       ///< size= was given (a top view's PNG fits it)
    sbrt::View view;   ///< the camera as asked for (map units, degrees)
    double zexag = 1;
    bool zexag_fitted = true; ///< no zexag=: RenderSession::load fits it to the model
    double light_azimuth = 315, light_elevation = 45, ambient = 0.35;
    std::array<uint8_t, 3> background{255, 255, 255};
    sbrt::Normals normals = sbrt::Normals::face;
    int kernel = 5;
    double smooth = 0;
    std::string color, rules; ///< colour table name or rules file
    std::vector<std::string> hide;           ///< class ids or labels
    std::vector<std::pair<std::string, double>> opacity; ///< class, alpha
    std::optional<double> opacity_length;    ///< map units (default a cell)
    std::vector<std::array<double, 6>> planes; ///< x,y,z,nx,ny,nz each
    std::optional<std::array<double, 4>> section; ///< x1,y1,x2,y2
    std::string fence;                       ///< vector line map
    std::string boreholes, layer = "1", where; ///< vector point map
    std::optional<double> borehole_radius;   ///< map units (default 0.4 cell)
    bool boreholes_only = false;             ///< -b
    std::string log_top, log_bottom, log_class; ///< columns of the logs
    sbrt::LogReference log_reference = sbrt::LogReference::elevation;
    bool split_logs = false;                 ///< -m
    std::vector<std::string> texture;        ///< one map, or red,green,blue
    double texture_blend = 1;
    std::string backend = "auto";
    std::string gpu_layout = "ssbo";         ///< layout=: ssbo or textures
    int threads = 0;
    bool walk_every_cell = false;            ///< -e: no empty-space skipping
    // an animation: frames of a path, those of range= rendered
    int frames = 1;
    sbrt::PathKind path = sbrt::PathKind::orbit;
    std::string path_map, keys;              ///< path=line's lines, path=keys' file
    std::optional<double> line_height;       ///< path=line: above the model's top
    double angle = 360;                      ///< the orbit's arc, degrees
    int first_frame = 1, last_frame = 1;     ///< range=
    std::string strds, video;                ///< outputs of the whole sequence
    double fps = 12;
    bool overwrite = false;                  ///< --overwrite: redo finished frames

    /// property= as given ("kans_5+kans_6").
    std::string property_title() const
    {
        std::string title;
        for (const std::string &name : property)
            title += (title.empty() ? "" : "+") + name;
        return title;
    }
};

/// \brief The parser's options and flags of the module.
struct RenderOptions {
    Option *input, *output, *material, *hit_elevation, *depth, *png;
    Flag *plain_png;
    Option *view, *size, *tile, *position, *target, *azimuth, *elevation, *distance, *fov,
        *ortho_height, *zexag;
    Option *light, *ambient, *background, *normals, *kernel, *smooth, *color,
        *rules;
    Option *hide, *opacity, *opacity_length, *plane, *section, *fence;
    Option *boreholes, *layer, *where, *borehole_radius, *log_top, *log_bottom,
        *log_class, *log_reference;
    Flag *boreholes_only, *split_logs;
    Option *texture, *texture_blend;
    Option *property, *property_color, *value, *select, *fade, *fade_range;
    Option *backend, *gpu_layout, *nprocs;
    Option *frames, *path, *angle, *path_map, *height, *keys, *range, *strds, *video,
        *fps;
    Flag *walk_every_cell;
};

/// \brief A request, or why the answers are not one (errors as values: the
/// command line fails with the message, the view server replies with it).
struct ParsedRequest {
    std::optional<RenderRequest> request;
    std::string error;
};

RenderOptions define_render_options();
/// The request of the options' answers, checked as G_parser does not.
ParsedRequest parse_render_request(const RenderOptions &options);

#endif
