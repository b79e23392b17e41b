/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The boreholes of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "boreholes_part.hpp"

#include <sstream>

#include "input_part.hpp"
#include "request_error.hpp"

namespace {

void define_logs(OptionTable &table)
{
    table.define_standard(G_OPT_DB_COLUMN, "log_top",
                          _("Column of the top of each logged interval"), _("Boreholes"));
    table.define_standard(G_OPT_DB_COLUMN, "log_bottom",
                          _("Column of the bottom of each logged interval"),
                          _("Boreholes"));
    table.define_standard(
        G_OPT_DB_COLUMN, "log_class",
        _("Column of the class of each logged interval (one row per interval)"),
        _("Boreholes"));
    table.define_choice("log_reference", _("What log_top= and log_bottom= measure"),
                        _("Boreholes"), "elevation", "elevation,depth",
                        _("elevation;Elevations (map z);"
                          "depth;Depths below the point's z (2D points: below the model's "
                          "surface at the point)"));
}

} // namespace

void BoreholesPart::define(OptionTable &table)
{
    Option *boreholes = table.define_standard(
        G_OPT_V_INPUT, "boreholes",
        _("Each point is drawn as a vertical cylinder "
          "showing the classes of the stack below "
          "it (or its logged intervals)"),
        _("Boreholes"));
    boreholes->label = _("Vector point map of boreholes");
    table.add(G_define_standard_option(G_OPT_V_FIELD))->guisection = _("Boreholes");
    table.add(G_define_standard_option(G_OPT_DB_WHERE))->guisection = _("Boreholes");
    table.define("borehole_radius", TYPE_DOUBLE,
                 _("Radius of the borehole cylinders, map units "
                   "(default: 0.4 of the cell size)"),
                 _("Boreholes"));
    define_logs(table);
    Flag *only =
        table.define_flag('b', _("Show only the boreholes, not the model"), _("Boreholes"));
    Flag *split = table.define_flag(
        'm', _("Split each borehole: its log on the left half, the model on the right"),
        _("Boreholes"));
    G_option_requires(only, boreholes, NULL);
    G_option_requires(split, table.option("log_class"), NULL);
    G_option_requires(table.option("log_class"), boreholes, NULL);
    G_option_requires_all(table.option("log_class"), table.option("log_top"),
                          table.option("log_bottom"), NULL);
}

void BoreholesPart::read(const Answers &a)
{
    boreholes = a.text("boreholes");
    check_map_name("boreholes", boreholes);
    layer = a.text("layer", "1");
    where = a.text("where");
    if (a.given("borehole_radius")) {
        borehole_radius = a.number("borehole_radius");
        if (!(*borehole_radius > 0))
            bad_request(_("borehole_radius= must be positive"));
    }
    boreholes_only = a.flag('b');
    log_top = a.text("log_top");
    log_bottom = a.text("log_bottom");
    log_class = a.text("log_class");
    log_reference = sbrt::parse_log_reference(a.text("log_reference", "elevation"));
    split_logs = a.flag('m');
    // what G_option_requires says on the command line, for every request
    if (boreholes_only && boreholes.empty())
        bad_request(_("-b shows only the boreholes: give boreholes="));
    if (split_logs && log_class.empty())
        bad_request(_("-m splits the boreholes' logs: give log_class="));
    if (!log_class.empty() && (boreholes.empty() || log_top.empty() || log_bottom.empty()))
        bad_request(_("log_class= needs boreholes=, log_top= and log_bottom="));
}

std::string BoreholesPart::key(const sbrt::Camera &camera) const
{
    std::ostringstream key;
    key << std::hexfloat << boreholes << ' ' << layer << ' ' << where << ' '
        << borehole_radius.value_or(-1) << ' ' << boreholes_only << ' ' << log_top << ' '
        << log_bottom << ' ' << log_class << ' ' << int(log_reference) << ' ' << split_logs;
    if (split_logs) // the log on the left half as the camera sees it
        key << ' ' << camera.du().x << ' ' << camera.du().y;
    return key.str();
}
