/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Option definitions (GUI sections as in m.nviz.image)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "render_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "animation_options.hpp"
#include "option_parts.hpp"
#include "util/error.hpp"
#include "scene/scene.hpp"
#include "request_error.hpp"

using namespace option_parts;

RenderOptions define_render_options()
{
    RenderOptions options;
    RenderOptions *o = &options;
    o->input = G_define_option();
    o->input->key = "input";
    o->input->type = TYPE_STRING;
    o->input->required = YES;
    o->input->key_desc = "name";
    o->input->gisprompt = "old,sbrt,sbrt";
    o->input->description = _("Name of the SBRT to render (from r3.sbrt.convert)");

    o->output = G_define_standard_option(G_OPT_R_BASENAME_OUTPUT);
    o->output->required = NO;
    o->output->description =
        _("The image as the map <output> (its own colours) and <output>.red, "
          ".green, .blue (frames: <output>_NNNN...); none: png= only");
    o->output->guisection = _("Output");
    o->material = define_map_output(
        "material", _("Raster map of the class of the first opaque hit"));
    o->hit_elevation = define_map_output(
        "hit_elevation", _("Raster map of the elevation (z) of the first hit"));
    o->depth = define_map_output(
        "depth", _("Raster map of the distance from the camera to the hit"));
    o->png = define_standard(G_OPT_F_OUTPUT, "png", _("PNG file of the image too"),
                             _("Output"));
    o->plain_png = define_flag(
        'n', _("No annotations in the PNG (legend, north arrow, vertical "
               "exaggeration, scale bar)"),
        _("Output"));

    o->view = define_choice(
        "view", _("Projection of the view"), _("Camera"), "perspective",
        "perspective,orthographic,top",
        _("perspective;Perspective camera;"
          "orthographic;Parallel rays along target - position;"
          "top;Straight down, one pixel per cell of the current region "
          "(georeferenced outputs)"));
    o->size = define("size", TYPE_INTEGER,
                     _("Image size in pixels (default: 640,480; view=top: the "
                       "maps have the region's cells, the PNG enlarges them by "
                       "whole pixels to fit this size, by default to 640 on "
                       "its longer side)"),
                     _("Camera"));
    o->size->key_desc = "width,height";
    o->tile = define("tile", TYPE_INTEGER,
                     _("Only this rectangle of the size= image: its first row and "
                       "column (from 0, top left) and its rows and columns; tiles "
                       "mosaic to the whole image exactly (r.patch)"),
                     _("Camera"));
    o->tile->key_desc = "row,col,rows,cols";
    o->position = define("position", TYPE_DOUBLE,
                         _("Camera position (map units, unexaggerated)"),
                         _("Camera"));
    o->position->key_desc = "x,y,z";
    o->target = define("target", TYPE_DOUBLE,
                       _("Point looked at (default: centre of the model)"),
                       _("Camera"));
    o->target->key_desc = "x,y,z";
    o->azimuth = define("azimuth", TYPE_DOUBLE,
                        _("Direction the camera looks from, degrees clockwise "
                          "from north (ignored with position=)"),
                        _("Camera"), "225");
    o->azimuth->options = "0-360";
    o->elevation = define("elevation", TYPE_DOUBLE,
                          _("Camera angle above the horizon, degrees (ignored "
                            "with position=)"),
                          _("Camera"), "30");
    o->elevation->options = "-90-90";
    o->distance = define("distance", TYPE_DOUBLE,
                         _("Distance from the target (default: frames the "
                           "model; ignored with position=)"),
                         _("Camera"));
    o->fov = define("fov", TYPE_DOUBLE,
                    _("Vertical field of view, degrees"), _("Camera"), "40");
    o->ortho_height = define("ortho_height", TYPE_DOUBLE,
                             _("Height of an orthographic view, map units "
                               "(default: frames the model)"),
                             _("Camera"));
    o->zexag = define("zexag", TYPE_DOUBLE,
                      _("Vertical exaggeration (about the model's bottom; default: "
                        "fitted to the model's extent and thickness)"),
                      _("Camera"));

    o->light = define("light", TYPE_DOUBLE,
                      _("Light direction: azimuth,elevation in degrees"),
                      _("Shading"), "315,45");
    o->light->key_desc = "azimuth,elevation";
    o->ambient = define("ambient", TYPE_DOUBLE,
                        _("Ambient light share (0-1)"), _("Shading"), "0.35");
    o->ambient->options = "0-1";
    o->background = G_define_standard_option(G_OPT_C);
    o->background->key = "background";
    o->background->answer = const_cast<char *>("white");
    o->background->description = _("Colour where rays miss the model");
    o->background->guisection = _("Shading");

    o->normals = define_choice(
        "normals", _("Surface normals for lighting"), _("Shading"), "face",
        "face,kernel",
        _("face;Exact normal of the cell wall, top or bottom that was hit;"
          "kernel;Image-space k x k x k kernel over the depth image "
          "(smoother, as in Graciano et al. 2018)"));
    o->kernel = define("kernel", TYPE_INTEGER,
                       _("Kernel size k of normals=kernel (odd)"),
                       _("Shading"), "5");
    o->kernel->options = "3-11";
    o->smooth = define("smooth", TYPE_DOUBLE,
                       _("Gaussian smoothing of the normals, sigma in pixels "
                         "(0: none)"),
                       _("Shading"), "0");
    o->color = G_define_standard_option(G_OPT_M_COLR);
    o->color->description =
        _("Colour table for the materials instead of their stored colours");
    o->color->guisection = _("Shading");
    o->rules = define_standard(
        G_OPT_F_INPUT, "rules",
        _("Lines of 'class colour', 'nv colour', 'default colour'; '-' reads stdin"),
        _("Shading"));
    o->rules->label = _("Colour rules for the materials (as r3.colors rules=)");

    o->hide = define("hide", TYPE_STRING,
                     _("A label that holds commas as it is, or without its commas"),
                     _("Strata"));
    o->hide->label = _("Classes not drawn: class ids, codes, short names or labels");
    o->hide->multiple = YES;
    o->hide->key_desc = "class";
    o->opacity = define("opacity", TYPE_STRING,
                        _("Translucent classes: class id, code, short name or "
                          "label and the share of light (0-1) it absorbs over "
                          "opacity_length"),
                        _("Strata"));
    o->opacity->multiple = YES;
    o->opacity->key_desc = "class:alpha";
    o->opacity_length = define("opacity_length", TYPE_DOUBLE,
                               _("Length over which opacity= alphas apply, map "
                                 "units (default: one cell)"),
                               _("Strata"));

    o->plane = define("plane", TYPE_DOUBLE,
                      _("Clip planes: a point and a normal each; the side the "
                        "normal points to is removed"),
                      _("Sections"));
    o->plane->multiple = YES;
    o->plane->key_desc = "x,y,z,nx,ny,nz";
    o->section = define("section", TYPE_DOUBLE,
                        _("Vertical cross section through two points: the side "
                          "facing the camera is removed"),
                        _("Sections"));
    o->section->key_desc = "x1,y1,x2,y2";
    o->fence = define_standard(G_OPT_V_INPUT, "fence",
                               _("Draws only the vertical curtains below its "
                                 "lines (with boreholes= the cylinders too)"),
                               _("Sections"));
    o->fence->label = _("Vector line map of a fence diagram");

    o->boreholes = define_standard(G_OPT_V_INPUT, "boreholes",
                                   _("Each point is drawn as a vertical cylinder "
                                     "showing the classes of the stack below "
                                     "it (or its logged intervals)"),
                                   _("Boreholes"));
    o->boreholes->label = _("Vector point map of boreholes");
    o->layer = G_define_standard_option(G_OPT_V_FIELD);
    o->layer->guisection = _("Boreholes");
    o->where = G_define_standard_option(G_OPT_DB_WHERE);
    o->where->guisection = _("Boreholes");
    o->borehole_radius = define("borehole_radius", TYPE_DOUBLE,
                                _("Radius of the borehole cylinders, map units "
                                  "(default: 0.4 of the cell size)"),
                                _("Boreholes"));
    o->log_top = define_standard(G_OPT_DB_COLUMN, "log_top",
                                 _("Column of the top of each logged interval"),
                                 _("Boreholes"));
    o->log_bottom = define_standard(G_OPT_DB_COLUMN, "log_bottom",
                                    _("Column of the bottom of each logged interval"),
                                    _("Boreholes"));
    o->log_class = define_standard(
        G_OPT_DB_COLUMN, "log_class",
        _("Column of the class of each logged interval (one row per interval)"),
        _("Boreholes"));
    o->log_reference = define_choice(
        "log_reference", _("What log_top= and log_bottom= measure"),
        _("Boreholes"), "elevation", "elevation,depth",
        _("elevation;Elevations (map z);"
          "depth;Depths below the point's z (2D points: below the model's "
          "surface at the point)"));
    o->boreholes_only =
        define_flag('b', _("Show only the boreholes, not the model"), _("Boreholes"));
    o->split_logs = define_flag(
        'm', _("Split each borehole: its log on the left half, the model on the right"),
        _("Boreholes"));

    o->texture = define_standard(
        G_OPT_R_INPUTS, "texture",
        _("One map with a colour table, or three maps red,green,blue (0-255)"),
        _("Drape"));
    o->texture->label = _("Raster map(s) draped on the terrain surface");
    o->texture_blend = define("texture_blend", TYPE_DOUBLE,
                              _("Share of the texture in the surface colour "
                                "(0: class colours, 1: texture only)"),
                              _("Drape"), "1");
    o->texture_blend->options = "0-1";

    o->property = define("property", TYPE_STRING,
                         _("Channels joined by + are added, e.g. kans_5+kans_6+kans_7 "
                           "(the probability of a group of classes)"),
                         _("Property"));
    o->property->label = _("Property channel to colour the model by (see r3.sbrt.convert -p)");
    o->property->key_desc = "name[+name...]";
    o->property_color = define("property_color", TYPE_STRING,
                               _("GRASS colour table (e.g. viridis, magma, bcyr) or a "
                                 "rules file (value red:green:blue lines, % allowed)"),
                               _("Property"), "viridis");
    o->property_color->key_desc = "table|file";
    o->select = define("select", TYPE_STRING,
                       _("Channels (joined by +), an operator (>=, >, <=, <, ==, !=) and a "
                         "number, e.g. kans_5+kans_6+kans_7>=60: a probability shell"),
                       _("Property"));
    o->select->label = _("Draw only the voxels whose property meets this condition");
    o->select->key_desc = "condition";
    o->fade = define("fade", TYPE_STRING,
                     _("e.g. onz_lk: 0 keeps the colour, the channel's highest value (100 "
                       "for %) turns it grey"),
                     _("Property"));
    o->fade->label = _("Uncertainty channel that greys the colours");
    o->fade->key_desc = "name";
    o->fade_range = define("fade_range", TYPE_DOUBLE,
                           _("Uncertainty of full colour and of grey (default: 0 and the "
                             "channel's highest value)"),
                           _("Property"));
    o->fade_range->key_desc = "low,high";
    o->value = define_map_output(
        "value", _("Raster map of the property at the first hit (with property=)"));
    o->value->guisection = _("Property");

    o->backend = define_choice(
        "backend", _("Renderer"), _("Settings"), "auto", "auto,egl,osmesa,cpu",
        _("auto;GPU through EGL, else OSMesa, else (or where the only "
          "OpenGL is a slower software one) the CPU ray caster;"
          "egl;OpenGL compute shader, headless EGL context;"
          "osmesa;OpenGL compute shader, OSMesa context (Mesa < 25.1);"
          "cpu;Exact multithreaded CPU ray caster"));
    o->gpu_layout = define_choice(
        "layout", _("How the GPU holds the model (OpenGL backends)"), _("Settings"),
        "ssbo", "ssbo,textures",
        _("ssbo;two storage buffers, cell offsets and intervals (5-SSBO);"
          "textures;an index texture over the grid and the intervals packed "
          "into a 2D texture (1-Textures; grids up to the largest texture)"));
    o->nprocs = G_define_standard_option(G_OPT_M_NPROCS);
    o->nprocs->answer = const_cast<char *>("0");
    o->nprocs->description = _("Number of threads (0: all cores)");
    o->nprocs->guisection = _("Settings");
    o->walk_every_cell = define_flag(
        'e', _("Walk every cell: no empty-space skipping (the same image, "
               "slower; for benchmarks)"),
        _("Settings"));

    define_animation_options(options);

    G_option_required(o->output, o->png, o->value, NULL);
    G_option_requires(o->strds, o->output, NULL);
    G_option_exclusive(o->color, o->rules, NULL);
    G_option_requires(o->boreholes_only, o->boreholes, NULL);
    G_option_requires(o->split_logs, o->log_class, NULL);
    G_option_requires(o->log_class, o->boreholes, NULL);
    G_option_requires_all(o->log_class, o->log_top, o->log_bottom, NULL);
    return options;
}

namespace {

/// A map name of option `key`: GRASS's look-ups copy names into buffers of
/// GNAME_MAX bytes (a longer name crashed G_find_file2), so a longer one is
/// refused here.
void check_map_name(const char *key, const std::string &name)
{
    if (name.size() >= GNAME_MAX)
        bad_request(_("%s=%s: a map name has at most %d characters"), key,
                    shortened(name, 40).c_str(), GNAME_MAX - 1);
}

/// The request of the answers; throws sbrt::Error (bad_request).
RenderRequest read_render_options(const RenderOptions &options)
{
    const RenderOptions *o = &options;
    RenderRequest r;
    r.input = o->input->answer;
    check_map_name("input", r.input);
    r.output = answer_or(o->output);
    r.material = answer_or(o->material);
    r.hit_elevation = answer_or(o->hit_elevation);
    r.depth = answer_or(o->depth);
    r.value = answer_or(o->value);
    const std::string property = answer_or(o->property);
    for (size_t from = 0; !property.empty() && from <= property.size();) {
        const size_t plus = std::min(property.find('+', from), property.size());
        const std::string name = property.substr(from, plus - from);
        from = plus + 1;
        if (name.empty())
            bad_request(_("property=%s: give channel names joined by +, e.g. "
                          "kans_5+kans_6"),
                        answer_or(o->property).c_str());
        r.property.push_back(name);
    }
    r.property_color = answer_or(o->property_color);
    r.select = answer_or(o->select);
    r.fade = answer_or(o->fade);
    if (o->fade_range->answers) {
        const std::vector<double> range = read_numbers(o->fade_range);
        if (range.size() != 2 || !(range[1] > range[0]))
            bad_request(_("fade_range= takes two numbers low,high with high above low, "
                          "e.g. fade_range=0,100"));
        r.fade_range = std::array<double, 2>{range[0], range[1]};
    }
    if (r.fade_range && r.fade.empty())
        bad_request(_("fade_range= needs fade= (the uncertainty channel)"));
    if (r.property_color.empty())
        r.property_color = "viridis";
    if (!r.value.empty() && r.property.empty())
        bad_request(_("value=%s needs property= (the channel whose value it holds)"),
                    r.value.c_str());
    r.png = answer_or(o->png);
    r.annotate = !o->plain_png->answer;
    sbrt::View &v = r.view;
    const std::string kind = o->view->answer;
    v.kind = kind == "top"            ? sbrt::ViewKind::top
             : kind == "orthographic" ? sbrt::ViewKind::orthographic
                                      : sbrt::ViewKind::perspective;
    if (o->size->answers) {
        const std::vector<double> size = read_numbers(o->size);
        if (size.size() != 2 || size[0] < 1 || size[1] < 1 ||
            size[0] != std::floor(size[0]) || size[1] != std::floor(size[1]) ||
            size[0] > 65536 || size[1] > 65536)
            bad_request(_("size= takes the image's width,height in pixels "
                            "(1 to 65536 each), e.g. size=1056,884"));
        r.width = int(size[0]);
        r.height = int(size[1]);
        r.size_given = true;
    }
    if (o->tile->answers) {
        const std::vector<double> t = read_numbers(o->tile);
        if (t.size() != 4 || t[0] < 0 || t[1] < 0 || t[2] < 1 || t[3] < 1 ||
            t[0] + t[2] > r.height || t[1] + t[3] > r.width)
            bad_request(_("tile= takes row,col,rows,cols of a rectangle within the "
                            "%d x %d image (size=), rows and columns from 0 at the "
                            "top left"),
                          r.width, r.height);
        if (v.kind == sbrt::ViewKind::top)
            bad_request(_("tile= is for perspective and orthographic views; a top "
                            "view's tile is a region (g.region)"));
        r.tile = {int(t[0]), int(t[1]), int(t[2]), int(t[3])};
    }
    v.position = read_point(o->position);
    v.target = read_point(o->target);
    v.azimuth = read_double(o->azimuth);
    v.elevation = read_double(o->elevation);
    if (o->distance->answer) {
        v.distance = read_double(o->distance);
        if (!(*v.distance > 0))
            bad_request(_("distance= must be positive"));
    }
    v.fov = read_double(o->fov);
    if (!(v.fov > 0 && v.fov < 180))
        bad_request(_("fov=%g: the field of view must lie between 0 and "
                        "180 degrees"),
                      v.fov);
    if (o->ortho_height->answer) {
        v.ortho_height = read_double(o->ortho_height);
        if (!(*v.ortho_height > 0))
            bad_request(_("ortho_height= must be positive"));
    }
    if (o->zexag->answer) {
        r.zexag = read_double(o->zexag);
        r.zexag_fitted = false;
    }
    if (!r.zexag_fitted && !(r.zexag > 0))
        bad_request(_("zexag=%g: the vertical exaggeration must be positive"),
                      r.zexag);
    const std::vector<double> light = read_numbers(o->light);
    if (light.size() != 2)
        bad_request(_("light= needs azimuth,elevation"));
    r.light_azimuth = light[0];
    r.light_elevation = light[1];
    r.ambient = read_double(o->ambient);
    int red, green, blue;
    if (G_str_to_color(o->background->answer, &red, &green, &blue) != 1)
        bad_request(_("background=<%s> is not a colour"), o->background->answer);
    r.background = {uint8_t(red), uint8_t(green), uint8_t(blue)};
    r.normals = std::string(o->normals->answer) == "kernel" ? sbrt::Normals::kernel
                                                            : sbrt::Normals::face;
    r.kernel = std::atoi(o->kernel->answer);
    if (r.tile && r.normals == sbrt::Normals::kernel)
        bad_request(_("tile= with normals=kernel: the kernel reads pixels across "
                        "the tile's edges, so tiles would not mosaic exactly; use "
                        "normals=face"));
    if (r.kernel % 2 == 0)
        bad_request(_("kernel=%d: the kernel size must be odd (3, 5, 7, 9 "
                        "or 11)"),
                      r.kernel);
    r.smooth = read_double(o->smooth);
    if (r.smooth < 0)
        bad_request(_("smooth=%g must not be negative"), r.smooth);
    r.color = answer_or(o->color);
    r.rules = answer_or(o->rules);
    for (char **a = o->hide->answers; a && *a; ++a)
        r.hide.emplace_back(*a);
    const std::vector<double> plane = read_numbers(o->plane);
    if (plane.size() % 6)
        bad_request(_("plane= takes six numbers per plane (x,y,z,nx,ny,nz), "
                        "not %zu"),
                      plane.size());
    if (plane.size() / 6 > size_t(sbrt::MAX_CLIP_PLANES))
        bad_request(_("plane= gives %zu planes; at most %d"), plane.size() / 6,
                      sbrt::MAX_CLIP_PLANES);
    for (size_t i = 0; i < plane.size(); i += 6) {
        std::array<double, 6> p;
        std::copy_n(plane.begin() + long(i), 6, p.begin());
        if (p[3] == 0 && p[4] == 0 && p[5] == 0)
            bad_request(_("plane=%g,%g,%g,%g,%g,%g: the normal is zero"), p[0],
                          p[1], p[2], p[3], p[4], p[5]);
        r.planes.push_back(p);
    }
    const std::vector<double> section = read_numbers(o->section);
    if (!section.empty()) {
        if (section.size() != 4)
            bad_request(_("section= takes four numbers x1,y1,x2,y2"));
        if (section[0] == section[2] && section[1] == section[3])
            bad_request(_("section=: the two points are the same"));
        r.section = {section[0], section[1], section[2], section[3]};
        if (r.planes.size() + 1 > size_t(sbrt::MAX_CLIP_PLANES))
            bad_request(_("plane= and section= give more than %d planes"),
                          sbrt::MAX_CLIP_PLANES);
    }
    // a class label that holds commas reaches here in parts (G_parser
    // parts answers at commas): a part with no colon is joined to the next
    std::string pair;
    for (char **a = o->opacity->answers; a && *a; ++a) {
        pair += (pair.empty() ? "" : ",") + std::string(*a);
        if (!std::strchr(*a, ':') && a[1])
            continue;
        const size_t colon = pair.rfind(':');
        char *end = nullptr;
        const double alpha = colon == std::string::npos
                                 ? NAN
                                 : std::strtod(pair.c_str() + colon + 1, &end);
        if (colon == std::string::npos || colon == 0 || *end ||
            !(alpha >= 0 && alpha <= 1))
            bad_request(_("opacity=%s: give class:alpha with alpha from 0 "
                            "(invisible) to 1 (opaque)"),
                          pair.c_str());
        r.opacity.emplace_back(pair.substr(0, colon), alpha);
        pair.clear();
    }
    if (o->opacity_length->answer) {
        r.opacity_length = read_double(o->opacity_length);
        if (!(*r.opacity_length > 0))
            bad_request(_("opacity_length= must be positive"));
    }
    r.fence = answer_or(o->fence);
    check_map_name("fence", r.fence);
    r.boreholes = answer_or(o->boreholes);
    check_map_name("boreholes", r.boreholes);
    r.layer = answer_or(o->layer, "1");
    r.where = answer_or(o->where);
    if (o->borehole_radius->answer) {
        r.borehole_radius = read_double(o->borehole_radius);
        if (!(*r.borehole_radius > 0))
            bad_request(_("borehole_radius= must be positive"));
    }
    r.boreholes_only = o->boreholes_only->answer;
    r.log_top = answer_or(o->log_top);
    r.log_bottom = answer_or(o->log_bottom);
    r.log_class = answer_or(o->log_class);
    r.log_reference = sbrt::parse_log_reference(o->log_reference->answer);
    r.split_logs = o->split_logs->answer;
    for (char **a = o->texture->answers; a && *a; ++a)
        r.texture.emplace_back(*a);
    for (const std::string &map : r.texture)
        check_map_name("texture", map);
    if (r.texture.size() != 0 && r.texture.size() != 1 && r.texture.size() != 3)
        bad_request(_("texture= takes one map (with its colour table) or three "
                        "maps red,green,blue, not %zu"),
                      r.texture.size());
    r.texture_blend = read_double(o->texture_blend);
    if (!(r.texture_blend >= 0 && r.texture_blend <= 1))
        bad_request(_("texture_blend=%g must lie in 0..1"), r.texture_blend);
    r.backend = o->backend->answer;
    r.gpu_layout = o->gpu_layout->answer;
    r.walk_every_cell = o->walk_every_cell->answer;
    r.threads = std::atoi(o->nprocs->answer);
    if (r.threads < 0)
        r.threads = std::max(1, int(std::thread::hardware_concurrency()) + r.threads);
    read_animation_options(*o, r);
    check_map_name("path_map", r.path_map);
    if (r.view.position && r.view.target && *r.view.position == *r.view.target)
        bad_request(_("position= and target= are the same point: the "
                        "camera has no direction"));
    return r;
}

} // namespace

ParsedRequest parse_render_request(const RenderOptions &options)
{
    try {
        return {read_render_options(options), {}};
    }
    catch (const sbrt::Error &e) {
        return {std::nullopt, e.what()};
    }
}
