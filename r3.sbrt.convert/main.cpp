/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Converts 3D raster maps and stacked horizons to a stack-based
 *            representation of terrains (SBRT) and back
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>

#include "convert.hpp"
#include "report.hpp"
#include "util/error.hpp"
#include "grass.hpp"
#include "module_options.hpp"
#include "sbrt_choices.hpp"
#include "sbrt_store.hpp"
#include "model/survey_presets.hpp"
#include "map_names.hpp"
#include "module_errors.hpp"

namespace {

struct Options {
    Option *input, *sbrt, *file, *variable, *output, *horizons, *materials,
        *bottom, *rules, *memory, *preset, *properties, *property, *format, *nprocs;
    Flag *reverse, *print, *shell, *list, *override_crs, *set_region, *all_properties;
};

Options define_options()
{
    Options o;
    o.input = G_define_standard_option(G_OPT_R3_INPUT);
    o.input->required = NO;
    o.input->description =
        _("3D raster map to convert (with -r, or -p/-g without output: an "
          "SBRT, as sbrt=)");

    o.sbrt = sbrt_grass::define_sbrt_option(
        "sbrt", _("Existing SBRT to expand into the 3D raster output= (-r) or to "
                  "describe (-p, -g)"));
    o.sbrt->required = NO;

    o.file = G_define_standard_option(G_OPT_F_INPUT);
    o.file->key = "file";
    o.file->required = NO;
    o.file->label = _("Multidimensional file to import (NetCDF, HDF5, Zarr)");
    o.file->description =
        _("Read through GDAL; with -p and no output=: list its variables");
    o.file->guisection = _("File");

    o.variable = G_define_option();
    o.variable->key = "variable";
    o.variable->type = TYPE_STRING;
    o.variable->key_desc = "name";
    o.variable->required = NO;
    o.variable->description =
        _("3D variable of file= (easting, northing, vertical) to convert");
    o.variable->guisection = _("File");

    o.properties = G_define_option();
    o.properties->key = "properties";
    o.properties->type = TYPE_STRING;
    o.properties->key_desc = "name";
    o.properties->multiple = YES;
    o.properties->required = NO;
    o.properties->label =
        _("Property channels: variables of file= on the same grid, or 3D raster "
          "maps beside input=");
    o.properties->description =
        _("Per-voxel values beside the classes (e.g. probabilities kans_1,...,"
          "onz_lk), kept exactly; 3D raster maps are read in the current 3D region");
    o.properties->guisection = _("Properties");

    o.all_properties = G_define_flag();
    o.all_properties->key = 'a';
    o.all_properties->description =
        _("Keep every other variable of file= on the classes' grid as a property "
          "channel");
    o.all_properties->guisection = _("Properties");

    o.property = G_define_option();
    o.property->key = "property";
    o.property->type = TYPE_STRING;
    o.property->key_desc = "name";
    o.property->required = NO;
    o.property->description =
        _("With -r: the property channel to expand instead of the classes");

    o.memory = G_define_standard_option(G_OPT_MEMORYMB);
    o.memory->description =
        _("Memory for a band of file= read at once (the SBRT is written band "
          "by band as it is converted)");
    o.memory->guisection = _("File");

    o.output = G_define_option();
    o.output->key = "output";
    o.output->type = TYPE_STRING;
    o.output->key_desc = "name";
    o.output->required = NO;
    o.output->description =
        _("Name of the SBRT to create (with -r: the 3D raster map)");

    o.horizons = G_define_standard_option(G_OPT_R_INPUTS);
    o.horizons->key = "horizons";
    o.horizons->required = NO;
    o.horizons->description =
        _("Raster maps of the top elevation of each unit, top to bottom");
    o.horizons->guisection = _("Horizons");

    o.materials = G_define_option();
    o.materials->key = "materials";
    o.materials->type = TYPE_INTEGER;
    o.materials->multiple = YES;
    o.materials->required = NO;
    o.materials->description = _("Class id of each unit, in horizons= order");
    o.materials->guisection = _("Horizons");

    o.bottom = G_define_option();
    o.bottom->key = "bottom";
    o.bottom->type = TYPE_STRING;
    o.bottom->required = NO;
    o.bottom->key_desc = "name|value";
    o.bottom->description =
        _("Base of the lowest unit: raster map or elevation (default: region "
          "bottom)");
    o.bottom->guisection = _("Horizons");

    o.rules = G_define_standard_option(G_OPT_F_INPUT);
    o.rules->key = "rules";
    o.rules->required = NO;
    o.rules->label = _("File of classification rules ('-' for standard input)");
    o.rules->description =
        _("Lines low:high:class[:label]; '*' is an open end; values no rule "
          "covers become empty");

    o.preset = G_define_option();
    o.preset->key = "preset";
    o.preset->type = TYPE_STRING;
    o.preset->required = NO;
    o.preset->answer = const_cast<char *>("auto");
    static const std::string presets = "auto,none," + sbrt::preset_names();
    o.preset->options = presets.c_str();
    o.preset->label = _("Survey preset: the published labels and colours of a survey");
    o.preset->description =
        _("auto: the one file= identifies itself as (e.g. GeoTOP); none: no preset");
    o.preset->guisection = _("File");

    o.reverse = G_define_flag();
    o.reverse->key = 'r';
    o.reverse->description =
        _("Reverse: expand the SBRT sbrt= (or input=) into the 3D raster map "
          "output=");
    o.set_region = G_define_flag();
    o.set_region->key = 's';
    o.set_region->label =
        _("Set the current region (2D and 3D) to the SBRT's grid");
    o.set_region->description =
        _("As g.region raster_3d= does: the SBRT of sbrt= (or input=), or the "
          "one output= makes; with -r before it expands");
    o.set_region->guisection = _("Region");
    o.print = G_define_flag();
    o.print->key = 'p';
    o.print->description =
        _("Print metadata and the memory comparison with the voxel model");
    o.print->guisection = _("Print");
    o.shell = G_define_flag();
    o.shell->key = 'g';
    o.shell->description = _("Print metadata in shell script style");
    o.shell->guisection = _("Print");
    o.format = sbrt_grass::define_format_option({sbrt_grass::OutputFormat::plain,
                                                 sbrt_grass::OutputFormat::shell,
                                                 sbrt_grass::OutputFormat::json});
    o.format->label = _("Output format of -p, -g and -l");
    o.format->description = _("shell: as -g; shell or json without -p: print as -p does");
    o.format->guisection = _("Print");
    o.list = G_define_flag();
    o.list->key = 'l';
    o.list->description = _("List the SBRTs in the search path and exit");
    o.list->guisection = _("Print");
    o.list->suppress_required = YES;
    o.override_crs = G_define_flag();
    o.override_crs->key = 'o';
    o.override_crs->label =
        _("Override the CRS check (take file='s coordinates as they are)");
    o.override_crs->description =
        _("Without it a file whose CRS differs from the location's is refused");
    o.override_crs->guisection = _("File");

    G_option_exclusive(o.input, o.horizons, o.sbrt, o.file, NULL);
    G_option_requires(o.variable, o.file, NULL);
    G_option_requires(o.properties, o.file, o.input, NULL);
    G_option_requires(o.all_properties, o.file, NULL);
    G_option_exclusive(o.properties, o.all_properties, NULL);
    G_option_requires(o.property, o.reverse, NULL);
    G_option_requires(o.override_crs, o.file, NULL);
    G_option_excludes(o.sbrt, o.rules, NULL);
    G_option_requires(o.materials, o.horizons, NULL);
    G_option_requires(o.horizons, o.materials, NULL);
    G_option_requires(o.bottom, o.horizons, NULL);
    G_option_excludes(o.reverse, o.horizons, o.rules, o.file, NULL);
    G_option_exclusive(o.print, o.shell, NULL);
    o.nprocs = sbrt_grass::define_nprocs();
    return o;
}

sbrt::Classifier read_classifier(const char *rules)
{
    if (!rules)
        return sbrt::Classifier();
    try {
        if (std::string(rules) == "-")
            return sbrt::Classifier::parse(std::cin, "rules=-");
        std::ifstream in(rules);
        if (!in)
            G_fatal_error(_("Unable to open rules file <%s>"), rules);
        return sbrt::Classifier::parse(in, rules);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Invalid classification rules: %s"), e.what());
    }
}

/// What the run converts, for its error messages: the SBRT made or read,
/// else the source.
std::string subject_of(const Options &o)
{
    for (const Option *option : {o.output, o.sbrt, o.input, o.file})
        if (option->answer)
            return option->answer;
    return "SBRT";
}

/// \brief A file of the mapset's temporary folder, removed where it is
/// still there when the run ends.
struct TemporaryFile {
    std::string path;
    /// A G_fatal_error exits past the destructor: its handler removes a
    /// half-written file too.
    TemporaryFile() { G_add_error_handler(remove_file, this); }
    TemporaryFile(const TemporaryFile &) = delete;
    TemporaryFile &operator=(const TemporaryFile &) = delete;
    ~TemporaryFile()
    {
        G_remove_error_handler(remove_file, this);
        remove_file(this);
    }

private:
    static void remove_file(void *self)
    {
        const std::string &path = static_cast<TemporaryFile *>(self)->path;
        if (!path.empty())
            std::remove(path.c_str());
    }
};

std::vector<std::string> answers_of(const Option *opt)
{
    std::vector<std::string> out;
    for (int i = 0; opt->answers && opt->answers[i]; ++i)
        out.push_back(opt->answers[i]);
    return out;
}

std::vector<int> integers_of(const Option *opt)
{
    std::vector<int> out;
    for (const std::string &a : answers_of(opt))
        out.push_back(std::atoi(a.c_str()));
    return out;
}

/// The grid of SBRT `name`: from its header where it has block summaries,
/// else from its model read whole.
sbrt::Frame frame_of(const char *name, const sbrt::ReadOptions &reading)
{
    if (const auto summary = sbrt_grass::read_sbrt_summary_map(name))
        return summary->frame;
    return sbrt_grass::read_sbrt_map(name, reading).frame();
}

/// -p, -g, format= and -s of existing SBRT `name`: from its block
/// summaries where it has them (format 2.1; a report of property channels
/// needs the model's spans), no block decoded; else from its model.
void describe(const char *name, bool report, bool set_region,
              sbrt_grass::OutputFormat format, const sbrt::ReadOptions &reading)
{
    const std::optional<sbrt::ModelSummary> summary = sbrt_grass::read_sbrt_summary_map(name);
    if (summary && !(report && summary->has_channels)) {
        if (set_region)
            set_region_to(name, summary->frame);
        if (report)
            print_description(name, description_of(*summary),
                              sbrt::stacks_file_info(sbrt_grass::find_sbrt(name)), format);
        return;
    }
    const sbrt::Model model = sbrt_grass::read_sbrt_map(name, reading);
    if (set_region)
        set_region_to(name, model.frame());
    if (report)
        print_report(name, model, sbrt::stacks_file_info(sbrt_grass::find_sbrt(name)), format,
                     sbrt_grass::read_channels_map(name, model).get());
}

/// Imports variable= of file= into SBRT `output` (at `path`), written band
/// by band as it is read; returns its frame.
sbrt::Frame import_file(const Options &o, const char *output, const std::string &path,
                        unsigned threads)
{
    if (!o.variable->answer)
        G_fatal_error(_("Give variable= (one of those r3.sbrt.convert -p "
                        "file=%s lists)"),
                      o.file->answer);
    sbrt::Classifier classifier = read_classifier(o.rules->answer);
    const int megabytes = std::atoi(o.memory->answer);
    if (megabytes < 1)
        G_fatal_error(_("memory=%s: give at least 1 (MB)"), o.memory->answer);
    const std::vector<std::string> properties =
        o.all_properties->answer ? same_grid_variables(o.file->answer, o.variable->answer)
                                 : answers_of(o.properties);
    if (o.all_properties->answer && properties.empty())
        G_warning(_("-a: file <%s> has no other variable on the grid of '%s'"),
                  o.file->answer, o.variable->answer);
    TemporaryFile channels_file; // the property channels, moved into the SBRT
    if (!properties.empty())
        channels_file.path = G_tempfile();
    return file_to_sbrt(o.file->answer, o.variable->answer, {output, path}, classifier,
                        o.override_crs->answer, size_t(megabytes) << 20, o.preset->answer,
                        properties, channels_file.path, threads);
}

void run(const Options &o)
{
    // -g is format=shell; format=shell or json asks for the report as -p does
    const sbrt_grass::OutputFormat format = sbrt_grass::read_output_format(o.format, o.shell);
    const unsigned threads = sbrt_grass::read_nprocs(o.nprocs);
    sbrt::ReadOptions reading;
    reading.threads = threads;
    if (o.list->answer) {
        if (format == sbrt_grass::OutputFormat::json)
            print_sbrt_list_json();
        else if (format == sbrt_grass::OutputFormat::shell)
            G_fatal_error(_("-l lists names, one a line (format=plain) or as JSON "
                            "(format=json): it has no shell style"));
        else
            for (const std::string &name : sbrt_grass::list_sbrts())
                fprintf(stdout, "%s\n", name.c_str());
        return;
    }
    const bool report = o.print->answer || format != sbrt_grass::OutputFormat::plain;
    const char *input = o.input->answer;
    const char *output = o.output->answer;
    const bool overwrite = G_check_overwrite(0, nullptr);
    // an existing SBRT: sbrt= (the dialogs' drop-down), or input= as before
    const char *sbrt = o.sbrt->answer ? o.sbrt->answer : input;

    const bool set_region = o.set_region->answer;
    if (o.reverse->answer) {
        if (!sbrt || !output)
            G_fatal_error(_("-r needs sbrt= (an SBRT) and output= (a new 3D "
                            "raster map)"));
        sbrt_grass::check_new_name(output, false, "output");
        sbrt_grass::check_new_raster3d(output, overwrite);
        if (set_region)
            set_region_to(sbrt, frame_of(sbrt, reading));
        if (o.property->answer)
            channel_to_voxels(sbrt, o.property->answer, output, threads);
        else
            sbrt_to_voxels(sbrt, output, threads);
        return;
    }
    if (o.sbrt->answer && output)
        G_fatal_error(_("sbrt=%s is an existing SBRT: with output= add -r to "
                        "expand it into a 3D raster map, or give input= (a 3D "
                        "raster map) to convert"),
                      o.sbrt->answer);
    if (o.file->answer && !output) {
        if (!report)
            G_fatal_error(_("Nothing to do: give output= (and variable=) to "
                            "import file=, or -p to list its variables"));
        if (format == sbrt_grass::OutputFormat::json)
            print_file_variables_json(o.file->answer);
        else
            print_file_variables(o.file->answer, format == sbrt_grass::OutputFormat::shell);
        return;
    }
    if (!output) {
        if (!sbrt || !(report || set_region))
            G_fatal_error(_("Nothing to do: give output= to convert, -p/-g "
                            "with sbrt= to describe an SBRT, or -s with sbrt= "
                            "to set the region to it"));
        describe(sbrt, report, set_region, format, reading);
        return;
    }
    // checked before the work, written after it
    sbrt_grass::check_new_name(output, true, "output");
    const std::string path = sbrt_grass::new_sbrt_path(output, overwrite);
    if (o.file->answer) {
        // written band by band as it is read: described from what was written
        const sbrt::Frame frame = import_file(o, output, path, threads);
        if (set_region)
            set_region_to(output, frame);
        else
            G_verbose_message(_("For -r, set the current region to the SBRT in one "
                                "step: r3.sbrt.convert -s sbrt=%s"),
                              output);
        if (report)
            describe(output, report, false, format, reading);
        return;
    }
    TemporaryFile channels_file; // the property channels, moved into the SBRT
    sbrt::Model model;
    std::string source;
    if (o.horizons->answers) {
        model = horizons_to_sbrt(answers_of(o.horizons),
                                 integers_of(o.materials), o.bottom->answer);
        source = std::string("horizons ") + o.horizons->answer;
    }
    else {
        if (!input)
            G_fatal_error(_("Give input= (3D raster map) or horizons="));
        sbrt::Classifier classifier = read_classifier(o.rules->answer);
        model = voxels_to_sbrt(input, classifier);
        source = std::string("3D raster map ") + input;
        const std::vector<std::string> properties = answers_of(o.properties);
        if (!properties.empty()) {
            channels_file.path = G_tempfile();
            raster3d_channels(properties, input, model, channels_file.path, threads);
            source += " with properties " + std::string(o.properties->answer);
        }
    }
    const std::string preset = o.preset->answer;
    if (preset != "auto" && preset != "none")
        apply_preset(preset, model);
    sbrt_grass::write_sbrt_map(output, path, model, source, channels_file.path, threads);
    if (set_region)
        set_region_to(output, model.frame());
    if (report)
        print_report(output, model, sbrt::stacks_file_info(path), format,
                     sbrt_grass::read_channels_map(output, model).get());
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("conversion"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("voxel"));
    G_add_keyword(_("SBRT"));
    G_add_keyword(_("NetCDF"));
    G_add_keyword(_("import"));
    module->description =
        _("Converts 3D raster maps, stacked horizons or NetCDF/HDF5/Zarr "
          "variables to a stack-based representation of terrains (SBRT) and "
          "back.");
    const Options options = define_options();
    sbrt_grass::offer_sbrts_in_dialog(options.sbrt, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    Rast3d_init_defaults();
    // a worker thread's exception is carried here (sbrt::for_each_row)
    sbrt_grass::run_reporting_errors(
        "converting", subject_of(options),
        _("convert a smaller region or use a larger machine"), [&] { run(options); });
    exit(EXIT_SUCCESS);
}
