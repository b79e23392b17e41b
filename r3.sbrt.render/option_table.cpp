/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   The module's options: definitions and G_parser's checks
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "option_table.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>

#include "request_error.hpp"
#include "util/error.hpp"

Option *OptionTable::define(const char *key, int type, const char *desc,
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
    return add(o);
}

Option *OptionTable::define_choice(const char *key, const char *desc, const char *section,
                                   const char *answer, const char *choices,
                                   const char *descriptions)
{
    Option *o = define(key, TYPE_STRING, desc, section, answer);
    o->options = choices;
    o->descriptions = descriptions;
    return o;
}

Option *OptionTable::define_standard(STD_OPT kind, const char *key, const char *desc,
                                     const char *section)
{
    Option *o = G_define_standard_option(kind);
    o->key = key;
    o->required = NO;
    o->description = desc;
    o->guisection = section;
    return add(o);
}

Option *OptionTable::define_map_output(const char *key, const char *desc)
{
    return define_standard(G_OPT_R_OUTPUT, key, desc, _("Output"));
}

Flag *OptionTable::define_flag(char key, const char *desc, const char *section)
{
    Flag *f = G_define_flag();
    f->key = key;
    f->description = desc;
    f->guisection = section;
    flags_.push_back(f);
    return f;
}

Option *OptionTable::add(Option *option)
{
    options_.push_back(option);
    return option;
}

void OptionTable::seal()
{
    infos_.clear();
    for (const Option *o : options_) {
        OptionInfo info;
        info.key = o->key;
        info.type = o->type;
        info.multiple = o->multiple == YES;
        info.choices = o->options ? o->options : "";
        info.key_desc = o->key_desc ? o->key_desc : "";
        if (o->answer)
            info.default_answer = o->answer;
        infos_.push_back(info);
    }
    flag_keys_.clear();
    for (const Flag *f : flags_)
        flag_keys_ += f->key;
}

Option *OptionTable::option(const char *key) const
{
    for (Option *o : options_)
        if (std::strcmp(o->key, key) == 0)
            return o;
    return nullptr;
}

std::vector<std::string> OptionTable::parsed_words() const
{
    std::vector<std::string> words;
    for (const Option *o : options_)
        if (o->answer)
            words.push_back(std::string(o->key) + "=" + o->answer);
    std::string flags;
    for (const Flag *f : flags_)
        if (f->answer)
            flags += f->key;
    if (!flags.empty())
        words.push_back("-" + flags);
    return words;
}

namespace {

/// Whether `value` is one of the choices of a string option, or each of
/// its numbers within the range of a numeric one, as G_parser checks.
bool allowed(const OptionInfo &info, const std::string &value)
{
    if (info.choices.empty())
        return true;
    if (info.type == TYPE_STRING) {
        const std::vector<std::string> choices = split_commas(info.choices);
        const std::vector<std::string> parts =
            info.multiple ? split_commas(value) : std::vector<std::string>{value};
        return std::all_of(parts.begin(), parts.end(), [&](const std::string &part) {
            return std::find(choices.begin(), choices.end(), part) != choices.end();
        });
    }
    const size_t dash = info.choices.find('-', 1);
    if (dash == std::string::npos)
        return true;
    const double low = std::strtod(info.choices.c_str(), nullptr),
                 high = std::strtod(info.choices.c_str() + dash + 1, nullptr);
    for (const std::string &part : split_commas(value)) {
        char *end = nullptr;
        const double v = std::strtod(part.c_str(), &end);
        if (part.empty() || *end || !(v >= low && v <= high))
            return false;
    }
    return true;
}

/// A value G_parser would refuse for its type or its number of values.
void check_shape(const OptionInfo &info, const std::string &value)
{
    const std::vector<std::string> parts = split_commas(value);
    if (info.type == TYPE_INTEGER || info.type == TYPE_DOUBLE)
        for (const std::string &part : parts) {
            char *end = nullptr;
            if (info.type == TYPE_INTEGER)
                std::strtol(part.c_str(), &end, 10);
            else
                std::strtod(part.c_str(), &end);
            if (part.empty() || *end)
                bad_request(_("%s=%s: <%s> is not %s"), info.key.c_str(),
                            shortened(value, 100).c_str(), shortened(part, 40).c_str(),
                            info.type == TYPE_INTEGER ? _("a whole number") : _("a number"));
        }
    const size_t fields = 1 + size_t(std::count(info.key_desc.begin(), info.key_desc.end(), ','));
    if (parts.size() % fields)
        bad_request(_("%s=%s: give %s%s"), info.key.c_str(), shortened(value, 100).c_str(),
                    info.key_desc.c_str(), info.multiple ? _(" (once or more)") : "");
}

} // namespace

Answers OptionTable::answer(const std::vector<std::string> &words) const
{
    std::map<std::string, std::string> values;
    std::string flags;
    for (const std::string &word : words) {
        if (word.size() > 1 && word[0] == '-' && word[1] != '-') {
            for (size_t k = 1; k < word.size(); ++k) {
                if (flag_keys_.find(word[k]) == std::string::npos)
                    bad_request(_("unknown flag -%s"),
                                shortened(std::string(1, word[k]), 8).c_str());
                flags += word[k];
            }
            continue;
        }
        const size_t equals = word.find('=');
        if (equals == std::string::npos || equals == 0)
            bad_request(_("<%s> is neither key=value nor a -flag"), shortened(word).c_str());
        const std::string key = word.substr(0, equals), value = word.substr(equals + 1);
        const auto info = std::find_if(infos_.begin(), infos_.end(),
                                       [&](const OptionInfo &i) { return i.key == key; });
        if (info == infos_.end())
            bad_request(_("unknown option <%s>"), shortened(key).c_str());
        if (value.empty())
            bad_request(_("%s=: give a value (or leave the option out)"), key.c_str());
        if (values.count(key))
            bad_request(_("%s= is given twice; give each option once"), key.c_str());
        if (!allowed(*info, value))
            bad_request(info->type == TYPE_STRING ? _("%s=%s: not one of %s")
                                                  : _("%s=%s: not within %s"),
                        key.c_str(), shortened(value).c_str(), info->choices.c_str());
        check_shape(*info, value);
        values[key] = value;
    }
    for (const OptionInfo &info : infos_)
        if (info.default_answer && !values.count(info.key))
            values[info.key] = *info.default_answer;
    return Answers(std::move(values), flags);
}
