/****************************************************************************
 * MODULE:    r3.sbrt.support
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Sets the labels and colours of an SBRT's classes after import,
 *            as r3.colors and r.category do for maps: GRASS colour tables,
 *            colour rules, another map's table, category rules, survey
 *            presets; and the unit and kind of property channels
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <chrono>
#include <cstdlib>
#include <optional>
#include <string>

#include "channel_changes.hpp"
#include "format/channels_rewrite.hpp"
#include "format/format.hpp"
#include "format/sbrt_lock.hpp"
#include "grass.hpp"
#include "input_file.hpp"
#include "legend_sources.hpp"
#include "model/legend_rules.hpp"
#include "model/survey_presets.hpp"
#include "module_options.hpp"
#include "raster_metadata.hpp"
#include "sbrt_choices.hpp"
#include "sbrt_store.hpp"
#include "util/error.hpp"
#include "module_errors.hpp"

namespace {

struct Options {
    Option *sbrt, *color, *rules, *raster, *raster_3d, *preset, *labels;
    Option *channel, *unit, *kind;
    Flag *remove;
};

Options define_options()
{
    Options o;
    o.sbrt = sbrt_grass::define_sbrt_option(
        "sbrt", _("SBRT of the current mapset whose labels and colours to set"));

    o.color = G_define_standard_option(G_OPT_M_COLR);
    o.color->description =
        _("GRASS colour table, stretched over the range of the class ids");
    o.color->guisection = _("Colours");

    o.rules = G_define_standard_option(G_OPT_F_INPUT);
    o.rules->key = "rules";
    o.rules->required = NO;
    o.rules->label = _("File of colour rules ('-' for standard input)");
    o.rules->description = _("As r3.colors rules=: lines 'class colour' (r:g:b or a name)");
    o.rules->guisection = _("Colours");

    o.raster = G_define_standard_option(G_OPT_R_INPUT);
    o.raster->key = "raster";
    o.raster->required = NO;
    o.raster->description = _("Raster map whose colours and category labels to take");
    o.raster->guisection = _("Colours");

    o.raster_3d = G_define_standard_option(G_OPT_R3_INPUT);
    o.raster_3d->key = "raster_3d";
    o.raster_3d->required = NO;
    o.raster_3d->description = _("3D raster map whose colours and category labels to take");
    o.raster_3d->guisection = _("Colours");

    o.preset = G_define_option();
    o.preset->key = "preset";
    o.preset->type = TYPE_STRING;
    o.preset->required = NO;
    o.preset->description = _("Survey preset: the published labels and colours of a survey");
    static const std::string names = sbrt::preset_names();
    o.preset->options = names.c_str();

    o.labels = G_define_standard_option(G_OPT_F_INPUT);
    o.labels->key = "labels";
    o.labels->required = NO;
    o.labels->label = _("File of category rules ('-' for standard input)");
    o.labels->description =
        _("As r.category rules=: lines 'class:label' or 'low:high:label'");
    o.labels->guisection = _("Labels");

    o.remove = G_define_flag();
    o.remove->key = 'r';
    o.remove->description =
        _("Remove the classes' own colours (the default palette draws them)");
    o.remove->guisection = _("Colours");

    // issue 51: what a property channel is (GeoTOP's kans_* come without units)
    o.channel = G_define_option();
    o.channel->key = "channel";
    o.channel->type = TYPE_STRING;
    o.channel->key_desc = "name";
    o.channel->required = NO;
    o.channel->multiple = YES;
    o.channel->description = _("Property channels whose unit and kind to set");
    o.channel->guisection = _("Channels");

    o.unit = G_define_option();
    o.unit->key = "unit";
    o.unit->type = TYPE_STRING;
    o.unit->required = NO;
    o.unit->label = _("Unit of the channels ('none' removes it)");
    o.unit->description = _("E.g. % for a probability in percent");
    o.unit->guisection = _("Channels");

    o.kind = G_define_option();
    o.kind->key = "kind";
    o.kind->type = TYPE_STRING;
    o.kind->required = NO;
    o.kind->options = sbrt::channel_kind_names();
    o.kind->label = _("What the channels' values are");
    o.kind->description = _("probability= of r3.sbrt.surface and r3.sbrt.volume sums "
                            "channels of kind probability (in %)");
    o.kind->descriptions = _("probability;a probability in % (0-100);"
                             "percentage;a share in % that is no probability;"
                             "uncertainty;a measure of uncertainty;"
                             "other;any other quantity");
    o.kind->guisection = _("Channels");

    G_option_exclusive(o.color, o.rules, o.raster, o.raster_3d, o.preset, o.remove, NULL);
    G_option_required(o.color, o.rules, o.raster, o.raster_3d, o.preset, o.labels,
                      o.remove, o.channel, NULL);
    G_option_requires(o.channel, o.unit, o.kind, NULL);
    G_option_requires(o.unit, o.channel, NULL);
    G_option_requires(o.kind, o.channel, NULL);
    return o;
}

/// The directory of SBRT `name`, which must be in the current mapset.
std::string own_sbrt(const char *name)
{
    const std::string dir = sbrt_grass::find_sbrt(name);
    char bare[GNAME_MAX], mapset[GMAPSET_MAX];
    const char *plain = G_name_is_fully_qualified(name, bare, mapset) ? bare : name;
    if (!G_find_file2(sbrt_grass::ELEMENT, plain, G_mapset()) ||
        (plain != name && std::string(mapset) != G_mapset()))
        G_fatal_error(_("SBRT <%s> is not in the current mapset <%s>: only its own "
                        "SBRTs can be changed; copy it here first (r3.sbrt.manage "
                        "copy=%s,%s)"),
                      name, G_mapset(), name, plain);
    return dir;
}

/// "WHAT changed: DATE by USER: COMMAND", a line of `hist`.
std::string history_line(const char *what = "legend")
{
    return std::string(what) + " changed: " + sbrt_grass::history_date() + " by " +
           G_whoami() + ": " + G_recreate_command() + "\n";
}

/// The SBRT's writers' lock: changes made at once are made one after the
/// other, so none is lost (issue 48, item 3); readers never take it.
sbrt::SbrtLock lock_for_change(const std::string &dir, const char *name)
{
    try {
        return sbrt_grass::lock_for_writing(dir);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("SBRT <%s> not changed: %s"), name, e.what());
    }
}

/// The rules files, read whole before the SBRT is locked.
struct Inputs {
    std::optional<RulesText> color_rules;
    std::vector<sbrt::ClassStyle> label_rules;
};

Inputs read_inputs(const Options &o)
{
    Inputs in;
    if (o.rules->answer)
        in.color_rules = RulesText{o.rules->answer, read_rules_file("rules", o.rules->answer)};
    if (o.labels->answer)
        in.label_rules =
            parse_label_rules({o.labels->answer, read_rules_file("labels", o.labels->answer)});
    return in;
}

void change_legend(const Options &o, const Inputs &in, const char *name,
                   std::vector<sbrt::Material> &materials)
{
    if (o.color->answer)
        colors_from_table(o.color->answer, materials);
    else if (in.color_rules)
        colors_from_rules(*in.color_rules, name, materials);
    else if (o.raster->answer || o.raster_3d->answer)
        legend_from_map(o.raster->answer ? o.raster->answer : o.raster_3d->answer,
                        o.raster_3d->answer != nullptr, materials);
    else if (o.preset->answer) {
        // the name held by a named string: GCC 14's -Wdangling-reference
        // takes a reference found from a temporary for one into it
        const std::string preset_name = o.preset->answer;
        const sbrt::SurveyPreset &preset = sbrt::find_preset(preset_name);
        const size_t changed = sbrt::apply_styles(materials, preset.classes);
        G_message(_("Preset %s (%s; from %s): %zu of %zu classes set"),
                  preset.name.c_str(), preset.title.c_str(), preset.reference.c_str(),
                  changed, materials.size() - 1);
    }
    else if (o.remove->answer)
        for (sbrt::Material &m : materials)
            m.has_color = false;
    if (o.labels->answer)
        apply_label_rules(in.label_rules, o.labels->answer, name, materials);
}

/// Whether the options change the legend (not only channels).
bool changes_legend(const Options &o)
{
    return o.color->answer || o.rules->answer || o.raster->answer || o.raster_3d->answer ||
           o.preset->answer || o.labels->answer || o.remove->answer;
}

void run(const Options &o)
{
    const char *name = o.sbrt->answer;
    const std::string dir = own_sbrt(name);
    const Inputs inputs = read_inputs(o);
    std::optional<ChannelChange> channel_change;
    if (o.channel->answers)
        channel_change = read_channel_change(o.channel->answers, o.unit->answer,
                                             o.kind->answer);
    // read -> change -> rewrite under the lock: a change made meanwhile
    // by another process would otherwise be overwritten by ours
    const sbrt::SbrtLock lock = lock_for_change(dir, name);
    sbrt::Model model = sbrt_grass::read_sbrt_map(name);
    // the channels' change checked before the legend is written: all or
    // nothing of a bad command
    std::shared_ptr<const sbrt::PropertyChannels> channels;
    std::vector<sbrt::ChannelInfo> infos;
    if (channel_change) {
        channels = sbrt_grass::read_channels_map(name, model);
        infos = changed_channels(channels.get(), *channel_change, name);
    }
    if (changes_legend(o)) {
        std::vector<sbrt::Material> &materials = model.materials();
        if (materials.size() < 2)
            G_fatal_error(_("SBRT <%s> has no classes"), name);
        change_legend(o, inputs, name, materials);
        sbrt::rewrite_legend(dir, model, history_line());
    }
    if (channel_change)
        sbrt::rewrite_channels(dir, *channels, infos, history_line("channels"));
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("color table"));
    G_add_keyword(_("categories"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("SBRT"));
    module->description =
        _("Sets the labels and colours of the classes of a stack-based "
          "representation of terrains (SBRT), and the unit and kind of its "
          "property channels.");
    const Options options = define_options();
    sbrt_grass::offer_own_sbrts_in_dialog(options.sbrt, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    sbrt_grass::run_reporting_errors("changing the legend of SBRT", options.sbrt->answer,
                                     _("free some memory"), [&] { run(options); });
    exit(EXIT_SUCCESS);
}
