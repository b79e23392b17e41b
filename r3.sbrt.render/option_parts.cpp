/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Small helpers to define options and to read their answers
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "option_parts.hpp"
#include "request_error.hpp"

#include <cmath>
#include <cstdlib>

namespace option_parts {

Option *define(const char *key, int type, const char *desc,
               const char *section, const char *answer)
{
    Option *o = G_define_option();
    o->key = key;
    o->type = type;
    o->required = NO;
    o->description = desc;
    o->guisection = section;
    if (answer)
        o->answer = const_cast<char *>(answer);
    return o;
}

/// A string option with a fixed list of `choices` ("a,b") and their
/// descriptions ("a;text;b;text") for the GUI.
Option *define_choice(const char *key, const char *desc, const char *section,
                      const char *answer, const char *choices,
                      const char *descriptions)
{
    Option *o = define(key, TYPE_STRING, desc, section, answer);
    o->options = choices;
    o->descriptions = descriptions;
    return o;
}

/// An optional GRASS standard option (G_OPT_*) under its own `key`.
Option *define_standard(STD_OPT kind, const char *key, const char *desc,
                        const char *section)
{
    Option *o = G_define_standard_option(kind);
    o->key = key;
    o->required = NO;
    o->description = desc;
    o->guisection = section;
    return o;
}

Option *define_map_output(const char *key, const char *desc)
{
    return define_standard(G_OPT_R_OUTPUT, key, desc, _("Output"));
}

Flag *define_flag(char key, const char *desc, const char *section)
{
    Flag *f = G_define_flag();
    f->key = key;
    f->description = desc;
    f->guisection = section;
    return f;
}

/// The answer of an optional option, or `otherwise`.
std::string answer_or(const Option *o, const char *otherwise)
{
    return o->answer ? o->answer : otherwise;
}

std::vector<double> read_numbers(const Option *o)
{
    std::vector<double> values;
    for (char **a = o->answers; a && *a; ++a) {
        char *end = nullptr;
        const double v = std::strtod(*a, &end);
        if (*end || !std::isfinite(v))
            bad_request(_("Option <%s>: <%s> is not a number"), o->key, *a);
        values.push_back(v);
    }
    return values;
}

/// x,y,z of a point option, if given.
std::optional<glm::dvec3> read_point(const Option *o)
{
    if (!o->answers)
        return std::nullopt;
    const std::vector<double> v = read_numbers(o);
    if (v.size() != 3)
        bad_request(_("Option <%s> needs three values x,y,z"), o->key);
    return glm::dvec3(v[0], v[1], v[2]);
}

double read_double(const Option *o)
{
    char *end = nullptr;
    const double v = std::strtod(o->answer, &end);
    if (*end || !std::isfinite(v))
        bad_request(_("Option <%s>: <%s> is not a number"), o->key, o->answer);
    return v;
}

} // namespace option_parts
