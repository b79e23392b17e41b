/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Hidden and translucent strata of a render request
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "strata_part.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "request_error.hpp"

void StrataPart::define(OptionTable &table)
{
    Option *o = table.define("hide", TYPE_STRING,
                             _("A label that holds commas as it is, or without its commas"),
                             _("Strata"));
    o->label = _("Classes not drawn: class ids, codes, short names or labels");
    o->multiple = YES;
    o->key_desc = "class";
    o = table.define("opacity", TYPE_STRING,
                     _("Translucent classes: class id, code, short name or "
                       "label and the share of light (0-1) it absorbs over "
                       "opacity_length"),
                     _("Strata"));
    o->multiple = YES;
    o->key_desc = "class:alpha";
    table.define("opacity_length", TYPE_DOUBLE,
                 _("Length over which opacity= alphas apply, map "
                   "units (default: one cell)"),
                 _("Strata"));
}

void StrataPart::read(const Answers &a)
{
    hide = a.parts("hide");
    // a class label that holds commas comes in parts (answers are split at
    // commas): a part with no colon is joined to the next
    const std::vector<std::string> parts = a.parts("opacity");
    std::string pair;
    for (size_t i = 0; i < parts.size(); ++i) {
        pair += (pair.empty() ? "" : ",") + parts[i];
        if (parts[i].find(':') == std::string::npos && i + 1 < parts.size())
            continue;
        const size_t colon = pair.rfind(':');
        char *end = nullptr;
        const double alpha = colon == std::string::npos
                                 ? NAN
                                 : std::strtod(pair.c_str() + colon + 1, &end);
        if (colon == std::string::npos || colon == 0 || *end || !(alpha >= 0 && alpha <= 1))
            bad_request(_("opacity=%s: give class:alpha with alpha from 0 "
                          "(invisible) to 1 (opaque)"),
                        pair.c_str());
        opacity.emplace_back(pair.substr(0, colon), alpha);
        pair.clear();
    }
    if (a.given("opacity_length")) {
        opacity_length = a.number("opacity_length");
        if (!(*opacity_length > 0))
            bad_request(_("opacity_length= must be positive"));
    }
}

std::string StrataPart::key() const
{
    std::ostringstream key;
    key << std::hexfloat;
    for (const std::string &name : hide)
        key << "hide " << name << '\n';
    for (const auto &[name, alpha] : opacity)
        key << "opacity " << name << ' ' << alpha << '\n';
    key << "length " << opacity_length.value_or(-1);
    return key.str();
}
