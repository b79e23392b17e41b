/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Lists, copies, renames and removes SBRTs (the mapset element
 *            sbrt/<name>) in GRASS's manner, since g.list, g.copy,
 *            g.rename and g.remove know only the elements of their
 *            element_list
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdlib>

#include "util/error.hpp"
#include "manage.hpp"
#include "output_format.hpp"
#include "module_options.hpp"
#include "sbrt_choices.hpp"
#include "module_errors.hpp"

namespace {

struct Options {
    Option *copy, *rename, *remove, *mapset, *format, *separator;
    Flag *list, *qualified, *force;
};

/// An option of name pairs, as g.copy and g.rename define theirs.
Option *define_pair_option(const char *key, const char *key_desc,
                           const char *description)
{
    Option *o = G_define_option();
    o->key = key;
    o->type = TYPE_STRING;
    o->key_desc = key_desc;
    o->required = NO;
    // no gisprompt: GRASS 8.2's dialogs have no picker for an element of
    // their own ("Not selectable element"); a text field takes the pairs
    o->description = description;
    return o;
}

Options define_options()
{
    Options o;
    o.copy = define_pair_option(
        "copy", "from,to",
        _("SBRT(s) to copy into the current mapset (from may be name@mapset)"));
    o.copy->guisection = _("Copy");
    o.rename = define_pair_option("rename", "old,new",
                                  _("SBRT(s) of the current mapset to rename"));
    o.rename->guisection = _("Rename");

    o.remove = sbrt_grass::define_sbrt_option("remove",
                                              _("SBRT(s) of the current mapset to remove"));
    o.remove->multiple = YES;
    o.remove->required = NO;
    o.remove->guisection = _("Remove");
    o.force = G_define_flag();
    o.force->key = 'f';
    o.force->description =
        _("Force removal (without it remove= only prints what it would "
          "remove)");
    o.force->guisection = _("Remove");

    o.list = G_define_flag();
    o.list->key = 'l';
    o.list->description = _("List the SBRTs (default: of the search path)");
    o.list->guisection = _("List");
    o.qualified = G_define_flag();
    o.qualified->key = 'm';
    o.qualified->description =
        _("Print fully-qualified names (including mapsets)");
    o.qualified->guisection = _("List");
    o.mapset = G_define_standard_option(G_OPT_M_MAPSET);
    o.mapset->multiple = YES;
    o.mapset->label =
        _("Name of mapset to list (default: current search path)");
    o.mapset->description =
        _("'.' for current mapset; '*' for all mapsets in location");
    o.mapset->guisection = _("List");

    o.format = sbrt_grass::define_format_option({sbrt_grass::OutputFormat::plain,
                                                 sbrt_grass::OutputFormat::json,
                                                 sbrt_grass::OutputFormat::csv});
    o.format->label = _("Output format of -l");
    o.format->guisection = _("List");
    o.separator = sbrt_grass::define_separator_option();
    o.separator->guisection = _("List");

    G_option_required(o.list, o.copy, o.rename, o.remove, NULL);
    G_option_exclusive(o.list, o.copy, o.rename, o.remove, NULL);
    G_option_requires(o.qualified, o.list, NULL);
    G_option_requires(o.mapset, o.list, NULL);
    G_option_requires(o.separator, o.list, NULL);
    G_option_requires(o.force, o.remove, NULL);
    return o;
}

void run(const Options &o)
{
    const bool overwrite = G_check_overwrite(0, nullptr);
    if (o.list->answer) {
        const sbrt_grass::OutputFormat format = sbrt_grass::read_output_format(o.format);
        print_sbrts(mapsets_to_list(o.mapset), o.qualified->answer, format,
                    sbrt_grass::read_csv_separator(o.separator, format));
    }
    else if (o.copy->answers)
        copy_sbrts(o.copy, overwrite);
    else if (o.rename->answers)
        rename_sbrts(o.rename, overwrite);
    else
        remove_sbrts(o.remove, o.force->answer);
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("map management"));
    G_add_keyword(_("list"));
    G_add_keyword(_("copy"));
    G_add_keyword(_("rename"));
    G_add_keyword(_("remove"));
    G_add_keyword(_("SBRT"));
    module->label = _("Lists, copies, renames and removes SBRTs.");
    module->description =
        _("Manages stack-based representations of terrains (SBRT) as "
          "g.list, g.copy, g.rename and g.remove manage maps.");
    // offers --overwrite in the usage, as g.copy and g.rename do
    module->overwrite = 1;
    const Options options = define_options();
    // in the dialog: a check box for each SBRT of the current mapset
    sbrt_grass::offer_own_sbrts_in_dialog(options.remove, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    sbrt_grass::run_reporting_errors("managing", "SBRTs", _("free some memory"),
                                     [&] { run(options); });
    exit(EXIT_SUCCESS);
}
