/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The names a model's classes answer to in list options
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/class_names.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "model/survey_presets.hpp"
#include "model/class_words.hpp"
#include "util/error.hpp"
#include "util/safe_text.hpp"

namespace sbrt {

namespace {

/// The longest list of classes an error message holds (bytes).
constexpr size_t MAX_LISTED_BYTES = 16000;
/// The most commas of a label a list's parts are joined again for (a
/// label with more is named without its commas): bounds resolve()'s work.
constexpr size_t MAX_JOINED_COMMAS = 32;

/// `text` with ASCII letters in lower case (as same_text compares).
std::string lower(std::string text)
{
    for (char &ch : text)
        ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return text;
}

/// `text` without commas, each run of blanks one space, trimmed.
std::string without_commas(const std::string &text)
{
    std::string out;
    bool blank = false;
    for (char ch : text) {
        if (ch == ',')
            continue;
        if (ch == ' ' || ch == '\t') {
            blank = true;
            continue;
        }
        if (blank && !out.empty())
            out += ' ';
        blank = false;
        out += ch;
    }
    return out;
}

/// The aliases preset `p` gives a class of id `id` labelled `label`: its
/// alias: lines where the preset's class `id` has this label.
void add_preset_aliases(const SurveyPreset &p, int32_t id, const std::string &label,
                        std::vector<std::string> &out)
{
    const auto style = std::find_if(p.classes.begin(), p.classes.end(),
                                    [&](const ClassStyle &s) {
                                        return s.low == id && s.high == id;
                                    });
    if (style == p.classes.end() || !style->has_label ||
        !same_text(trim(style->label), trim(label)))
        return;
    for (const ClassAlias &a : p.aliases)
        if (a.id == id &&
            std::none_of(out.begin(), out.end(),
                         [&](const std::string &o) { return same_text(o, a.name); }))
            out.push_back(a.name);
}

} // namespace

ClassNames::ClassNames(const std::vector<Material> &materials)
    : ClassNames(materials, survey_presets())
{
}

ClassNames::ClassNames(const std::vector<Material> &materials,
                       const std::vector<SurveyPreset> &presets)
    : materials_(materials), aliases_(materials.size())
{
    // the first material of a name wins (emplace keeps what is there)
    for (uint32_t m = 1; m < materials_.size(); ++m) {
        const Material &material = materials_[m];
        by_id_.emplace(material.id, m);
        if (material.label.empty())
            continue;
        for (const SurveyPreset &p : presets)
            add_preset_aliases(p, material.id, material.label, aliases_[m]);
        by_label_.emplace(lower(trim(material.label)), m);
        by_bare_label_.emplace(lower(without_commas(material.label)), m);
        const size_t commas = size_t(std::count(material.label.begin(), material.label.end(), ','));
        if (commas) {
            // what a label's first part is, to the most commas after it
            size_t &most = label_heads_[lower(trim(material.label.substr(0, material.label.find(','))))];
            most = std::min(MAX_JOINED_COMMAS, std::max(most, commas));
        }
    }
    for (uint32_t m = 1; m < materials_.size(); ++m)
        for (const std::string &alias : aliases_[m])
            by_alias_.emplace(lower(alias), m);
}

uint32_t ClassNames::find_label(const std::string &label) const
{
    const auto found = by_label_.find(lower(label));
    return found == by_label_.end() ? EMPTY : found->second;
}

uint32_t ClassNames::find(const std::string &given) const
{
    const std::string name = trim(given);
    if (name.empty())
        return EMPTY;
    int32_t id = 0;
    if (parse_class_id(name, id)) {
        const auto found = by_id_.find(id);
        if (found != by_id_.end())
            return found->second;
    }
    const auto alias = by_alias_.find(lower(name));
    if (alias != by_alias_.end())
        return alias->second;
    if (const uint32_t m = find_label(name))
        return m;
    const auto bare = by_bare_label_.find(lower(without_commas(name)));
    return bare == by_bare_label_.end() ? EMPTY : bare->second;
}

std::vector<uint32_t> ClassNames::resolve(const std::vector<std::string> &names,
                                          const std::string &option,
                                          const std::string &what) const
{
    std::vector<uint32_t> out;
    for (size_t i = 0; i < names.size();) {
        // a label GRASS parted at its commas: the longest run of answers,
        // from one that begins a label with commas, that makes one
        size_t taken = 0;
        const auto head = label_heads_.find(lower(trim(names[i])));
        const size_t last =
            head == label_heads_.end() ? i : std::min(names.size() - 1, i + head->second);
        for (size_t j = last; j > i && !taken; --j) {
            std::string joined = names[i];
            for (size_t k = i + 1; k <= j; ++k)
                joined += "," + names[k];
            if (const uint32_t m = find_label(trim(joined))) {
                out.push_back(m);
                taken = j - i + 1;
            }
        }
        if (!taken) {
            out.push_back(resolve_one(names[i], option, what));
            taken = 1;
        }
        i += taken;
    }
    return out;
}

uint32_t ClassNames::resolve_one(const std::string &name, const std::string &option,
                                 const std::string &what) const
{
    if (const uint32_t m = find(name))
        return m;
    fail(option, ": no class of ", what, " is named '", fit_bytes(printable(trim(name)), 200),
         "' (an id, code, short name or label; a label that holds commas may be "
         "given as it is, quoted, or without its commas); the classes by id: ",
         accepted());
}

std::string ClassNames::accepted() const
{
    std::vector<uint32_t> order;
    for (uint32_t m = 1; m < materials_.size(); ++m)
        order.push_back(m);
    if (order.empty())
        return "none (the model is empty)";
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return materials_[a].id < materials_[b].id;
    });
    std::string out;
    for (size_t i = 0; i < order.size(); ++i) {
        const Material &m = materials_[order[i]];
        std::string names = m.label.empty() ? "" : fit_bytes(printable(m.label), 300);
        const std::vector<std::string> &aliases = aliases_[order[i]];
        for (size_t k = 0; k < aliases.size(); ++k)
            names += (k ? ", " : names.empty() ? "also " : "; also ") + printable(aliases[k]);
        const std::string entry = std::to_string(m.id) + (names.empty() ? "" : " (" + names + ")");
        if (out.size() + entry.size() > MAX_LISTED_BYTES)
            return out + ", and " + std::to_string(order.size() - i) +
                   " more (r3.sbrt.convert -p sbrt=NAME lists them all)";
        out += (i ? ", " : "") + entry;
    }
    return out;
}

} // namespace sbrt
