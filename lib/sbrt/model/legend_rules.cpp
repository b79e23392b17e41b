/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Category rules and survey presets: parsing and applying
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/legend_rules.hpp"

#include <fnmatch.h>

#include <algorithm>

#include "model/class_words.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt {

namespace {

/// "r:g:b", each 0-255, or false.
bool parse_rgb(const std::string &text, ClassStyle &style)
{
    int channel[3];
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t colon = k < 2 ? text.find(':', start) : text.size();
        if (colon == std::string::npos)
            return false;
        int32_t v;
        if (!parse_class_id(text.substr(start, colon - start), v) || v < 0 || v > 255)
            return false;
        channel[k] = v;
        start = colon + 1;
    }
    style.red = uint8_t(channel[0]);
    style.green = uint8_t(channel[1]);
    style.blue = uint8_t(channel[2]);
    style.has_color = true;
    return true;
}

/// "alias: ID NAME[, NAME...]": other names of class ID (its code, a short
/// name); commas part them, as GRASS parts a list option's answers.
void add_aliases(SurveyPreset &p, const std::string &rest, const std::string &what,
                 int number)
{
    const auto gap = rest.find_first_of(" \t");
    ClassAlias alias;
    if (gap == std::string::npos || !parse_class_id(rest.substr(0, gap), alias.id))
        fail(what, " line ", number, ": expected alias: ID NAME[, NAME...]");
    const std::string names = rest.substr(gap) + ",";
    for (size_t start = 0, comma; (comma = names.find(',', start)) != std::string::npos;
         start = comma + 1) {
        alias.name = trim(names.substr(start, comma - start));
        int32_t number_name;
        if (alias.name.empty() || alias.name.size() > MAX_ALIAS_BYTES ||
            printable(alias.name) != alias.name || parse_class_id(alias.name, number_name))
            fail(what, " line ", number, ": alias '", fit_bytes(printable(alias.name), 80),
                 "' must be a name of 1 to ", MAX_ALIAS_BYTES,
                 " printable bytes that is not a number");
        p.aliases.push_back(alias);
    }
}

/// Each alias names a class of the preset, and one class only: no other
/// class has it as alias or label.
void check_aliases(const SurveyPreset &p, const std::string &what)
{
    for (size_t i = 0; i < p.aliases.size(); ++i) {
        const ClassAlias &a = p.aliases[i];
        bool known = false;
        for (const ClassStyle &s : p.classes) {
            known = known || (s.low == a.id && s.high == a.id);
            if (s.has_label && same_text(s.label, a.name) && s.low != a.id)
                fail(what, ": alias ", a.name, " of class ", a.id, " is the label of class ",
                     s.low);
        }
        if (!known)
            fail(what, ": alias ", a.name, " names class ", a.id,
                 ", which has no class line");
        for (size_t j = 0; j < i; ++j)
            if (same_text(p.aliases[j].name, a.name) && p.aliases[j].id != a.id)
                fail(what, ": alias ", a.name, " names both class ", p.aliases[j].id,
                     " and class ", a.id);
    }
}

} // namespace

namespace {

/// "channel: PATTERN KIND [UNIT]" (issue 51): what the property channels
/// whose names match PATTERN are; a probability is in %.
ChannelRule parse_channel_rule(const std::string &rest, const std::string &what,
                               int number)
{
    std::vector<std::string> words;
    for (size_t at = 0; at < rest.size();) {
        const size_t start = rest.find_first_not_of(" \t", at);
        if (start == std::string::npos)
            break;
        at = std::min(rest.size(), rest.find_first_of(" \t", start));
        words.push_back(rest.substr(start, at - start));
    }
    ChannelRule rule;
    if (words.size() < 2 || words.size() > 3 || !parse_channel_kind(words[1], rule.kind))
        fail(what, " line ", number, ": expected channel: PATTERN KIND [UNIT], KIND one of ",
             channel_kind_names());
    rule.pattern = words[0];
    rule.unit = words.size() == 3 ? valid_utf8(words[2]) : "";
    if (rule.kind == ChannelKind::probability) {
        if (!rule.unit.empty() && rule.unit != "%")
            fail(what, " line ", number, ": a probability is in %, not in ", rule.unit);
        rule.unit = "%";
    }
    return rule;
}

} // namespace

std::vector<ClassStyle> parse_category_rules(std::istream &in, const std::string &what)
{
    std::vector<ClassStyle> rules;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#')
            continue;
        // id:label, or low:high:label where the second field is an id
        ClassStyle s;
        const auto colon = t.find(':');
        if (colon == std::string::npos || !parse_class_id(t.substr(0, colon), s.low))
            fail(what, " line ", number, ": expected id:label or low:high:label");
        s.high = s.low;
        std::string rest = t.substr(colon + 1);
        const auto second = rest.find(':');
        int32_t high;
        if (second != std::string::npos && parse_class_id(rest.substr(0, second), high)) {
            if (high < s.low)
                fail(what, " line ", number, ": range ", s.low, ":", high, " runs backwards");
            s.high = high;
            rest = rest.substr(second + 1);
        }
        s.label = valid_utf8(trim(rest));
        s.has_label = true;
        rules.push_back(s);
    }
    return rules;
}

SurveyPreset parse_preset(std::istream &in, const std::string &what)
{
    SurveyPreset p;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#')
            continue;
        const auto space = t.find_first_of(" \t");
        const std::string head = t.substr(0, space);
        const std::string rest = space == std::string::npos ? "" : trim(t.substr(space));
        if (head.size() > 1 && head.back() == ':') {
            const std::string key = head.substr(0, head.size() - 1);
            if (rest.empty())
                fail(what, " line ", number, ": ", key, ": has no value");
            if (key == "name")
                p.name = rest;
            else if (key == "title")
                p.title = rest;
            else if (key == "reference")
                p.reference = rest;
            else if (key == "variable")
                p.variables.push_back(rest);
            else if (key == "match") {
                const auto gap = rest.find_first_of(" \t");
                if (gap == std::string::npos)
                    fail(what, " line ", number, ": expected match: ATTRIBUTE PATTERN");
                p.matches.emplace_back(rest.substr(0, gap), trim(rest.substr(gap)));
            }
            else if (key == "channel")
                p.channels.push_back(parse_channel_rule(rest, what, number));
            else if (key == "alias")
                add_aliases(p, rest, what, number);
            else
                fail(what, " line ", number, ": unknown key ", key,
                     " (name, title, reference, variable, match, alias, channel)");
            continue;
        }
        // id red:green:blue label
        ClassStyle s;
        const auto gap = rest.find_first_of(" \t");
        const std::string color = rest.substr(0, gap);
        if (!parse_class_id(head, s.low) || !parse_rgb(color, s))
            fail(what, " line ", number, ": expected id red:green:blue label");
        s.high = s.low;
        s.label = gap == std::string::npos ? "" : valid_utf8(trim(rest.substr(gap)));
        s.has_label = !s.label.empty();
        p.classes.push_back(s);
    }
    if (p.name.empty() || p.reference.empty() || p.classes.empty())
        fail(what, ": a preset needs name:, reference: (where its legend comes from) "
                   "and at least one class line");
    check_aliases(p, what);
    return p;
}

bool preset_matches(const SurveyPreset &preset, const std::string &variable,
                    const std::vector<std::pair<std::string, std::string>> &attributes)
{
    bool named = false;
    for (const std::string &v : preset.variables)
        named = named || v == variable;
    if (!named)
        return false;
    for (const auto &[key, pattern] : preset.matches)
        for (const auto &[name, value] : attributes)
            if (name == key && fnmatch(pattern.c_str(), trim(value).c_str(), FNM_CASEFOLD) == 0)
                return true;
    return false;
}

size_t apply_styles(std::vector<Material> &materials, const std::vector<ClassStyle> &styles,
                    bool keep_own)
{
    size_t changed = 0;
    for (size_t i = 1; i < materials.size(); ++i) {
        Material &m = materials[i];
        const Material before = m;
        const bool own_label = !m.label.empty(), own_color = m.has_color;
        for (const ClassStyle &s : styles) {
            if (m.id < s.low || m.id > s.high)
                continue;
            if (s.has_label && !(keep_own && own_label))
                m.label = s.label;
            if (s.has_color && !(keep_own && own_color)) {
                m.red = s.red;
                m.green = s.green;
                m.blue = s.blue;
                m.has_color = true;
            }
        }
        if (m.label != before.label || m.has_color != before.has_color ||
            m.red != before.red || m.green != before.green || m.blue != before.blue)
            ++changed;
    }
    return changed;
}

} // namespace sbrt
