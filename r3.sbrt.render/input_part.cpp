/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   input=, color= and rules=
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "input_part.hpp"

#include "request_error.hpp"
#include "module_options.hpp"

void check_map_name(const char *key, const std::string &name)
{
    if (name.size() >= GNAME_MAX)
        bad_request(_("%s=%s: a map name has at most %d characters"), key,
                    shortened(name, 40).c_str(), GNAME_MAX - 1);
}

void InputPart::define(OptionTable &table)
{
    table.add(sbrt_grass::define_sbrt_option(
        "input", _("Name of the SBRT to render (from r3.sbrt.convert)")));
    Option *memory = table.add(sbrt_grass::define_memory(
        _("Maximum memory to be used (in MB) by this process, where the CPU decodes the "
          "model's blocks as its rays reach them (default: 300, or the least that works)")));
    memory->answer = nullptr; // given or not: the default gives way, a value does not
    memory->guisection = _("Settings");
}

void InputPart::read(const Answers &a)
{
    input = a.text("input");
    if (input.empty())
        bad_request(_("the request names no input="));
    check_map_name("input", input);
    const std::string memory = a.text("memory");
    memory_given = !memory.empty();
    memory_bytes = memory_given ? sbrt_grass::memory_bytes_of(memory.c_str()) : DEFAULT_MEMORY;
    if (!memory_bytes)
        bad_request(_("memory=%s is not a number of MB of at least 1"), memory.c_str());
}

std::string InputPart::key() const
{
    return input + '\n' + std::to_string(memory_bytes) + (memory_given ? " given" : "");
}

void ColorsPart::define(OptionTable &table)
{
    Option *color = table.add(G_define_standard_option(G_OPT_M_COLR));
    color->description = _("Colour table for the materials instead of their stored colours");
    color->guisection = _("Shading");
    Option *rules = table.define_standard(
        G_OPT_F_INPUT, "rules",
        _("Lines of 'class colour', 'nv colour', 'default colour'; '-' reads stdin"),
        _("Shading"));
    rules->label = _("Colour rules for the materials (as r3.colors rules=)");
    G_option_exclusive(color, rules, NULL);
}

void ColorsPart::read(const Answers &a)
{
    color = a.text("color");
    rules = a.text("rules");
    if (!color.empty() && !rules.empty())
        bad_request(_("color= and rules= both colour the classes: give one of them"));
}

std::string ColorsPart::key() const
{
    return color + '\n' + rules;
}
