/****************************************************************************
 * MODULE:    r3.sbrt.profile
 * PURPOSE:   The module's options and what a run asks for
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "profile_request.hpp"

#include <cmath>
#include <cstdlib>

#include "module_options.hpp"
#include "output_format.hpp"

ProfileOptions define_profile_options()
{
    ProfileOptions o;
    o.input = sbrt_grass::define_sbrt_option("input", _("Name of the SBRT to cut (from r3.sbrt.convert)"));

    o.coordinates = G_define_standard_option(G_OPT_M_COORDS);
    o.coordinates->multiple = YES;
    o.coordinates->description =
        _("Vertices of the profile's line, in order (two or more points)");
    o.coordinates->guisection = _("Line");
    o.line = G_define_standard_option(G_OPT_V_MAP);
    o.line->key = "line";
    o.line->required = NO;
    o.line->label = _("Name of a vector map whose line the profile follows");
    o.line->description = _("Its first line, or the line of cat=");
    o.line->guisection = _("Line");
    o.cat = G_define_option();
    o.cat->key = "cat";
    o.cat->type = TYPE_INTEGER;
    o.cat->required = NO;
    o.cat->description = _("Category (layer 1) of the line to follow in line=");
    o.cat->guisection = _("Line");

    o.output = G_define_standard_option(G_OPT_R_OUTPUT);
    o.output->required = NO;
    o.output->label = _("Name for the class profile raster map");
    o.output->description = _("Columns along the line (x: distance from its start), rows in "
                               "elevation (y: height), one row per layer of the model");
    o.output->guisection = _("Output");
    o.resolution = G_define_option();
    o.resolution->key = "resolution";
    o.resolution->type = TYPE_DOUBLE;
    o.resolution->required = NO;
    o.resolution->label = _("Step along the line of the profile map (map units)");
    o.resolution->description = _("Default: the model's finer horizontal resolution");
    o.resolution->guisection = _("Output");
    o.png = G_define_standard_option(G_OPT_F_OUTPUT);
    o.png->key = "png";
    o.png->required = NO;
    o.png->label = _("Name for the profile's figure (PNG)");
    o.png->description = _("Axes, the classes cut, the exaggeration and a location map");
    o.png->guisection = _("Output");
    o.zexag = G_define_option();
    o.zexag->key = "zexag";
    o.zexag->type = TYPE_DOUBLE;
    o.zexag->required = NO;
    o.zexag->label = _("Vertical exaggeration of the figure");
    o.zexag->description = _("Default: fitted to the line's length and the layers' thickness");
    o.zexag->guisection = _("Output");
    o.width = G_define_option();
    o.width->key = "width";
    o.width->type = TYPE_INTEGER;
    o.width->required = NO;
    o.width->answer = const_cast<char *>("1000");
    o.width->options = "100-8000";
    o.width->description = _("Width of the figure's profile in pixels");
    o.width->guisection = _("Output");

    o.shell = G_define_flag();
    o.shell->key = 'g';
    o.shell->description = _("Print the map's window and the figure's axes in shell script "
                             "style");

    G_option_required(o.coordinates, o.line, NULL);
    G_option_exclusive(o.coordinates, o.line, NULL);
    G_option_requires(o.cat, o.line, NULL);
    o.format = sbrt_grass::define_format_option(
        {sbrt_grass::OutputFormat::shell, sbrt_grass::OutputFormat::json}, false);
    o.format->label = _("Print the map's window and the figure's axes in this format");
    o.format->description = _("shell: as -g");
    o.nprocs = sbrt_grass::define_nprocs();
    o.memory = sbrt_grass::define_memory(
        _("Maximum memory to be used (in MB) by this process: the blocks of the SBRT "
          "are decoded as their columns are read, and dropped when it is full"));

    G_option_required(o.output, o.png, o.shell, o.format, NULL);
    return o;
}

namespace {

std::optional<double> positive_number(const Option *o)
{
    if (!o->answer)
        return std::nullopt;
    const double value = std::strtod(o->answer, nullptr);
    if (!(value > 0) || !std::isfinite(value))
        G_fatal_error(_("%s=%s: give a number above 0"), o->key, o->answer);
    return value;
}

} // namespace

ProfileRequest read_profile_request(const ProfileOptions &o)
{
    ProfileRequest r;
    r.input = o.input->answer;
    r.vertices = sbrt_grass::read_coordinate_pairs(o.coordinates);
    r.line = o.line->answer ? o.line->answer : "";
    if (o.cat->answer)
        r.cat = std::atoi(o.cat->answer);
    r.output = o.output->answer ? o.output->answer : "";
    r.resolution = positive_number(o.resolution);
    r.png = o.png->answer ? o.png->answer : "";
    r.zexag = positive_number(o.zexag);
    r.width = std::atoi(o.width->answer);
    r.print = sbrt_grass::read_output_format(o.format, o.shell);
    r.threads = sbrt_grass::read_nprocs(o.nprocs);
    r.memory_bytes = sbrt_grass::read_memory(o.memory);
    return r;
}
