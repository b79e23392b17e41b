/****************************************************************************
 * MODULE:    r3.sbrt.volume
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Volumes of the classes (or a class set) of an SBRT in the
 *            region or per area of a vector map, exact at the model's
 *            heights, as a table, JSON or CSV
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdlib>

#include "sbrt_choices.hpp"
#include "util/error.hpp"
#include "volume.hpp"
#include "module_errors.hpp"
#include "module_options.hpp"
#include "sbrt_bands.hpp"
#include "output_format.hpp"

namespace {

using sbrt_grass::OutputFormat;

struct Options {
    Option *input, *classes, *probability, *areas, *layer, *format, *separator, *output, *nprocs, *memory;
};

Options define_options()
{
    Options o;
    o.input = sbrt_grass::define_sbrt_option("input", _("Name of the input SBRT"));
    o.classes = G_define_option();
    o.classes->key = "classes";
    o.classes->type = TYPE_STRING;
    o.classes->key_desc = "class";
    o.classes->multiple = YES;
    o.classes->required = NO;
    o.classes->label = _("Classes of one set, measured together: class ids, codes, "
                         "short names or labels");
    o.classes->description = _("Default: every class, one row each. A label that holds "
                               "commas as it is, or without its commas");

    o.probability = sbrt_grass::define_probability(
        _("Probability whose expected volume to report too (e.g. beside classes=5,6,7, "
          "the volume where sand is the most likely class)"));

    o.areas = G_define_standard_option(G_OPT_V_INPUT);
    o.areas->key = "areas";
    o.areas->required = NO;
    o.areas->label = _("Vector map of areas: volumes per area category");
    o.areas->description = _("Cells whose centre lies inside an area count for its category");
    o.areas->guisection = _("Areas");
    o.layer = G_define_standard_option(G_OPT_V_FIELD);
    o.layer->guisection = _("Areas");

    o.format = sbrt_grass::define_format_option(
        {OutputFormat::plain, OutputFormat::json, OutputFormat::csv});
    o.format->guisection = _("Output");
    o.separator = sbrt_grass::define_separator_option();
    o.separator->guisection = _("Output");
    o.output = G_define_standard_option(G_OPT_F_OUTPUT);
    o.output->required = NO;
    o.output->description = _("Name of the output file (default: standard output)");
    o.output->guisection = _("Output");
    o.nprocs = sbrt_grass::define_nprocs();
    o.memory = sbrt_grass::define_memory(
        _("Maximum memory to be used (in MB) for the model's stacks: it is read band "
          "by band within it"));
    // no G_option_requires(layer, areas): pygrass and the GUI pass the
    // default layer=1 with every call
    return o;
}

VolumeRequest read_options(const Options &o)
{
    VolumeRequest r;
    r.input = o.input->answer;
    for (char **a = o.classes->answers; a && *a; ++a)
        r.classes.emplace_back(*a);
    r.areas = o.areas->answer ? o.areas->answer : "";
    r.probability = o.probability->answer ? o.probability->answer : "";
    r.layer = o.layer->answer ? o.layer->answer : "1";
    r.format = sbrt_grass::read_output_format(o.format);
    r.separator = sbrt_grass::read_csv_separator(o.separator, r.format);
    r.output = o.output->answer ? o.output->answer : "";
    r.threads = sbrt_grass::read_nprocs(o.nprocs);
    r.memory = sbrt_grass::read_memory(o.memory);
    return r;
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("volume"));
    G_add_keyword(_("statistics"));
    G_add_keyword(_("SBRT"));
    module->label = _("Volumes of the classes of an SBRT in the region or per area.");
    module->description =
        _("Sums the thickness of each class (or of a set of classes) of a stack-based "
          "terrain model (SBRT) times the cell area over the model's cells in the "
          "region or in the areas of a vector map.");
    const Options options = define_options();
    sbrt_grass::offer_sbrts_in_dialog(options.input, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const VolumeRequest request = read_options(options);
    sbrt_grass::run_reporting_errors("measuring", request.input, _("set a smaller region"),
                                     [&] { report_volumes(request); });
    exit(EXIT_SUCCESS);
}
