/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Labels and colours of classes as text: category rules
 *            ("id:label", as r.category rules=) and survey presets (a
 *            rules file per published legend, presets/NAME.rules), and how
 *            they are applied to a model's materials
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_LEGEND_RULES_HPP
#define SBRT_LEGEND_RULES_HPP

#include <cstdint>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "model/property_channel.hpp"

namespace sbrt {

/// \brief What a rule says about one class (or a range of ids).
struct ClassStyle {
    int32_t low = 0, high = 0; ///< ids low..high (one id: low == high)
    std::string label;
    bool has_label = false;
    uint8_t red = 0, green = 0, blue = 0;
    bool has_color = false;
};

/// Category rules as r.category rules= reads them: "id:label" or
/// "low:high:label" a line, '#' comments and blank lines skipped. Throws
/// sbrt::Error "what line N: ..." on the first bad line.
std::vector<ClassStyle> parse_category_rules(std::istream &in, const std::string &what);

/// \brief Another name of a preset's class (an "alias:" line): the
/// survey's own code (TNO's "zf", "BX") or a short name ("fine sand").
struct ClassAlias {
    int32_t id = 0;
    std::string name;
};

/// Longest alias a preset may give (bytes).
constexpr size_t MAX_ALIAS_BYTES = 64;

/// \brief What a preset says about property channels (a "channel:" line,
/// issue 51): those whose name matches `pattern` (fnmatch) are of `kind`,
/// in `unit`, where the file gives them no unit.
struct ChannelRule {
    std::string pattern;
    ChannelKind kind = ChannelKind::other;
    std::string unit; ///< "" where the line gives none ("%" for a probability)
};

/// \brief A survey's published legend, with how its files identify
/// themselves.
struct SurveyPreset {
    std::string name;      ///< preset= key, e.g. geotop_lithoclass
    std::string title;     ///< e.g. "GeoTOP lithoclasses"
    std::string reference; ///< where the labels and colours come from
    std::vector<std::string> variables; ///< variable names it applies to
    /// global attribute name and fnmatch pattern (case-insensitive): a file
    /// whose variable is one of `variables` is this survey when any holds
    std::vector<std::pair<std::string, std::string>> matches;
    std::vector<ClassStyle> classes;
    std::vector<ClassAlias> aliases; ///< alias: lines, in file order
    std::vector<ChannelRule> channels; ///< channel: lines, in file order
};

/// Parses a preset: "key: value" lines (name, title, reference, variable,
/// match "ATTRIBUTE PATTERN", alias "ID NAME[, NAME...]"), then class
/// lines "id red:green:blue label"; '#' comments. An alias is at most
/// MAX_ALIAS_BYTES of printable UTF-8, no comma, not a whole number, and
/// names one class of the preset only. Throws sbrt::Error "what line N:
/// ..." where a line is bad or name/reference/classes are missing.
/// "channel: PATTERN KIND [UNIT]" lines say what property channels are
/// (ChannelRule; KIND one of channel_kind_names(), a probability in %).
SurveyPreset parse_preset(std::istream &in, const std::string &what);

/// Whether a variable `variable` of a file with global string attributes
/// `attributes` (name, value) is this survey's.
bool preset_matches(const SurveyPreset &preset, const std::string &variable,
                    const std::vector<std::pair<std::string, std::string>> &attributes);

/// Applies `styles` to `materials` (index 0, EMPTY, untouched): each class
/// a style covers gets its label and colour, the later style winning. With
/// `keep_own`, a class keeps a label or colour it already has. Returns how
/// many materials changed.
size_t apply_styles(std::vector<Material> &materials, const std::vector<ClassStyle> &styles,
                    bool keep_own = false);

} // namespace sbrt

#endif
