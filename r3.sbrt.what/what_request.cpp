/****************************************************************************
 * MODULE:    r3.sbrt.what
 * PURPOSE:   Options of r3.sbrt.what, named and related as r.what's and
 *            v.what's (coordinates=, points=, layer=, where=, output=) and
 *            format= as GRASS's newer modules offer it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "what_request.hpp"
#include "module_options.hpp"
#include "output_format.hpp"

#include <cstdlib>
#include <cstring>

WhatOptions define_what_options()
{
    WhatOptions o;
    o.input =
        sbrt_grass::define_sbrt_option("input", _("Name of the SBRT to query (from r3.sbrt.convert)"));

    o.coordinates = G_define_standard_option(G_OPT_M_COORDS);
    o.coordinates->multiple = YES;
    o.coordinates->description = _("Coordinates of the columns to log");
    o.coordinates->guisection = _("Points");

    o.points = G_define_standard_option(G_OPT_V_MAP);
    o.points->key = "points";
    o.points->required = NO;
    o.points->label = _("Name of vector points map whose columns to log");
    o.points->guisection = _("Points");
    o.layer = G_define_standard_option(G_OPT_V_FIELD);
    o.layer->guisection = _("Points");
    o.where = G_define_standard_option(G_OPT_DB_WHERE);
    o.where->guisection = _("Points");

    o.format = sbrt_grass::define_format_option({sbrt_grass::OutputFormat::plain,
                                                 sbrt_grass::OutputFormat::json,
                                                 sbrt_grass::OutputFormat::csv});
    o.format->descriptions = _("plain;A log per point, top to bottom (readable);"
                               "json;A list of points, each with its intervals;"
                               "csv;One row per interval (with a header)");
    o.format->guisection = _("Output");
    o.separator = sbrt_grass::define_separator_option();
    o.separator->guisection = _("Output");
    o.output = G_define_standard_option(G_OPT_F_OUTPUT);
    o.output->required = NO;
    o.output->description = _("Name for output file (if omitted or \"-\" output to stdout)");
    o.output->guisection = _("Output");

    o.voxels = G_define_flag();
    o.voxels->key = 'v';
    o.voxels->label = _("Print each property channel voxel by voxel");
    o.voxels->description =
        _("plain: a table of the voxels after each point's layers; csv: a row per voxel "
          "after each point's layers, told apart by the column kind (json lists the "
          "voxels whatever this flag says)");
    o.voxels->guisection = _("Output");

    o.nprocs = sbrt_grass::define_nprocs();
    o.memory = sbrt_grass::define_memory(
        _("Maximum memory to be used (in MB) by this process: the blocks of the SBRT "
          "are decoded as their columns are read, and dropped when it is full"));

    G_option_required(o.coordinates, o.points, NULL);
    G_option_exclusive(o.coordinates, o.points, NULL);
    G_option_requires(o.where, o.points, NULL);
    return o;
}

WhatRequest read_what_request(const WhatOptions &o)
{
    WhatRequest r;
    r.input = o.input->answer;
    for (const glm::dvec2 &p : sbrt_grass::read_coordinate_pairs(o.coordinates))
        r.coordinates.push_back({p.x, p.y});
    r.points = o.points->answer ? o.points->answer : "";
    r.layer = o.layer->answer ? o.layer->answer : "1";
    r.where = o.where->answer ? o.where->answer : "";
    r.format = sbrt_grass::read_output_format(o.format);
    r.separator = sbrt_grass::read_csv_separator(o.separator, r.format);
    r.output = o.output->answer ? o.output->answer : "";
    r.voxels = o.voxels->answer;
    r.threads = sbrt_grass::read_nprocs(o.nprocs);
    r.memory_bytes = sbrt_grass::read_memory(o.memory);
    return r;
}
