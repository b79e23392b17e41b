/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The property view and the selection of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "property_part.hpp"

#include <algorithm>
#include <sstream>

#include "request_error.hpp"

void PropertyPart::define(OptionTable &table)
{
    Option *o = table.define("property", TYPE_STRING,
                             _("Channels joined by + are added, e.g. kans_5+kans_6+kans_7 "
                               "(the probability of a group of classes)"),
                             _("Property"));
    o->label = _("Property channel to colour the model by (see r3.sbrt.convert -p)");
    o->key_desc = "name[+name...]";
    o = table.define("property_color", TYPE_STRING,
                     _("GRASS colour table (e.g. viridis, magma, bcyr) or a "
                       "rules file (value red:green:blue lines, % allowed)"),
                     _("Property"), "viridis");
    o->key_desc = "table|file";
    SelectionPart::define(table); // between them in the dialog, as it always was
    o = table.define("fade", TYPE_STRING,
                     _("e.g. onz_lk: 0 keeps the colour, the channel's highest value (100 "
                       "for %) turns it grey"),
                     _("Property"));
    o->label = _("Uncertainty channel that greys the colours");
    o->key_desc = "name";
    o = table.define("fade_range", TYPE_DOUBLE,
                     _("Uncertainty of full colour and of grey (default: 0 and the "
                       "channel's highest value)"),
                     _("Property"));
    o->key_desc = "low,high";
    o = table.define_map_output(
        "value", _("Raster map of the property at the first hit (with property=)"));
    o->guisection = _("Property");
}

void PropertyPart::read_fade(const Answers &a)
{
    fade = a.text("fade");
    if (a.given("fade_range")) {
        const std::vector<double> range = a.numbers("fade_range");
        if (range.size() != 2 || !(range[1] > range[0]))
            bad_request(_("fade_range= takes two numbers low,high with high above low, "
                          "e.g. fade_range=0,100"));
        fade_range = std::array<double, 2>{range[0], range[1]};
    }
    if (fade_range && fade.empty())
        bad_request(_("fade_range= needs fade= (the uncertainty channel)"));
}

void PropertyPart::read(const Answers &a)
{
    const std::string given = a.text("property");
    for (size_t from = 0; !given.empty() && from <= given.size();) {
        const size_t plus = std::min(given.find('+', from), given.size());
        const std::string name = given.substr(from, plus - from);
        from = plus + 1;
        if (name.empty())
            bad_request(_("property=%s: give channel names joined by +, e.g. "
                          "kans_5+kans_6"),
                        given.c_str());
        property.push_back(name);
    }
    property_color = a.text("property_color", "viridis");
    read_fade(a);
    value = a.text("value");
    if (!value.empty() && property.empty())
        bad_request(_("value=%s needs property= (the channel whose value it holds)"),
                    value.c_str());
}

std::string PropertyPart::key() const
{
    std::ostringstream key;
    key << std::hexfloat << property_title() << '\n' << property_color << '\n' << fade;
    if (fade_range)
        key << ' ' << (*fade_range)[0] << ' ' << (*fade_range)[1];
    return key.str();
}

std::string PropertyPart::property_title() const
{
    std::string title;
    for (const std::string &name : property)
        title += (title.empty() ? "" : "+") + name;
    return title;
}

void SelectionPart::define(OptionTable &table)
{
    Option *o = table.define("select", TYPE_STRING,
                             _("Channels (joined by +), an operator (>=, >, <=, <, ==, !=) "
                               "and a number, e.g. kans_5+kans_6+kans_7>=60: a "
                               "probability shell"),
                             _("Property"));
    o->label = _("Draw only the voxels whose property meets this condition");
    o->key_desc = "condition";
}

void SelectionPart::read(const Answers &a)
{
    select = a.text("select");
}
