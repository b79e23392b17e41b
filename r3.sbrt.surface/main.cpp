/****************************************************************************
 * MODULE:    r3.sbrt.surface
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   2D raster maps of a class set of an SBRT: elevation of its
 *            top and base, its thickness, its number of layers and the
 *            depth of its top below the model's surface, exact at the
 *            model's heights
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdlib>

#include "sbrt_choices.hpp"
#include "surface.hpp"
#include "util/error.hpp"
#include "module_errors.hpp"
#include "module_options.hpp"
#include "sbrt_bands.hpp"

namespace {

struct Options {
    Option *input, *classes, *top, *base, *thickness, *layers, *depth, *probability,
        *expected_thickness, *nprocs, *memory;
};

Option *define_output(const char *key, const char *description)
{
    Option *o = G_define_standard_option(G_OPT_R_OUTPUT);
    o->key = key;
    o->required = NO;
    o->description = description;
    o->guisection = _("Output");
    return o;
}

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
    o.classes->label = _("Classes of the set: class ids, codes, short names or labels");
    o.classes->description = _("Names are compared without regard to case; a label that "
                               "holds commas as it is, or without its commas");

    o.top = define_output("top", _("Elevation of the highest top of the set"));
    o.base = define_output("base", _("Elevation of the lowest bottom of the set"));
    o.thickness = define_output("thickness", _("Total thickness of the set in the column"));
    o.layers = define_output("layers",
                             _("Number of separate layers of the set (adjacent classes "
                               "of the set are one layer)"));
    o.depth = define_output("depth",
                            _("Depth of the set's top below the model's surface (the "
                              "column's highest solid top)"));
    o.probability = sbrt_grass::define_probability(
        _("Probability whose expected thickness to map (expected_thickness=)"));
    o.expected_thickness = define_output(
        "expected_thickness", _("Expected thickness: the sum over the column's voxels of "
                                "probability / 100 times the voxel height"));
    o.expected_thickness->guisection = _("Probability");
    o.nprocs = sbrt_grass::define_nprocs();
    o.memory = sbrt_grass::define_memory(
        _("Maximum memory to be used (in MB) for the model's stacks: it is read band "
          "by band within it"));
    G_option_required(o.top, o.base, o.thickness, o.layers, o.depth, o.expected_thickness,
                      NULL);
    G_option_requires(o.expected_thickness, o.probability, NULL);
    G_option_requires(o.probability, o.expected_thickness, NULL);
    G_option_requires(o.top, o.classes, NULL);
    G_option_requires(o.base, o.classes, NULL);
    G_option_requires(o.thickness, o.classes, NULL);
    G_option_requires(o.layers, o.classes, NULL);
    G_option_requires(o.depth, o.classes, NULL);
    return o;
}

SurfaceRequest read_options(const Options &o)
{
    SurfaceRequest r;
    r.input = o.input->answer;
    for (char **a = o.classes->answers; a && *a; ++a)
        r.classes.emplace_back(*a);
    const auto answer = [](const Option *opt) {
        return std::string(opt->answer ? opt->answer : "");
    };
    r.top = answer(o.top);
    r.base = answer(o.base);
    r.thickness = answer(o.thickness);
    r.layers = answer(o.layers);
    r.depth = answer(o.depth);
    r.probability = answer(o.probability);
    r.expected_thickness = answer(o.expected_thickness);
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
    G_add_keyword(_("thickness"));
    G_add_keyword(_("isopach"));
    G_add_keyword(_("probability"));
    G_add_keyword(_("SBRT"));
    module->label = _("Tops, bases, thickness, layers and depth of a class set of an SBRT "
                      "as 2D raster maps.");
    module->description =
        _("Measures a set of classes of a stack-based terrain model (SBRT) in every "
          "cell of the current region, exactly at the model's heights.");
    const Options options = define_options();
    sbrt_grass::offer_sbrts_in_dialog(options.input, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const SurfaceRequest request = read_options(options);
    sbrt_grass::run_reporting_errors("measuring", request.input, _("set a smaller region"),
                                     [&] { make_surfaces(request); });
    exit(EXIT_SUCCESS);
}
