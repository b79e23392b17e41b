/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The names a model's classes answer to in list options
 *            (classes=, hide=, opacity=): class id, alias (a survey's code
 *            or short name, from its preset), label
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CLASS_NAMES_HPP
#define SBRT_CLASS_NAMES_HPP

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/legend_rules.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief Resolves the names of a model's classes.
///
/// A class answers to, in this order:
///  1. its id ("8");
///  2. an alias, compared without regard to case ("g", "gravel", "BX"):
///     class ID of a survey preset lends its alias: lines to the model's
///     class of the same id whose label is that preset class's label. So
///     the aliases follow the preset's names wherever the model carries
///     them (on import, after r3.sbrt.support preset=, in SBRTs written
///     before aliases existed) and never name a class the user relabelled;
///  3. its label, without regard to case;
///  4. its label with its commas left out ("clayey sand sandy clay loam
///     (kleiig zand zandige klei en leem)"), spaces and case aside.
/// A list's names (resolve()) may also give a label with its commas as it
/// is: GRASS parts an option's answer at commas, and the parts that make a
/// label together are joined again (a label of up to 32 commas; one with
/// more is named without them).
class ClassNames {
public:
    /// Names of `materials` (index 0, EMPTY, has none), aliases from the
    /// embedded survey presets.
    explicit ClassNames(const std::vector<Material> &materials);
    /// Aliases from `presets`.
    ClassNames(const std::vector<Material> &materials,
               const std::vector<SurveyPreset> &presets);

    /// Material index of the class `name` names, or EMPTY (0) for none.
    uint32_t find(const std::string &name) const;
    /// Material indices of a list option's answers, in their order (a
    /// label's parts joined again); throws sbrt::Error "OPTION: no class
    /// of WHAT is named 'NAME' (...); the classes by id: ..." on the first
    /// name no class answers to.
    std::vector<uint32_t> resolve(const std::vector<std::string> &names,
                                  const std::string &option,
                                  const std::string &what = "the model") const;
    /// One name; throws as resolve().
    uint32_t resolve_one(const std::string &name, const std::string &option,
                         const std::string &what = "the model") const;

    /// Aliases of a material, as its preset spells them.
    const std::vector<std::string> &aliases(uint32_t material) const
    {
        return aliases_.at(material);
    }
    /// Every class by id with its names: "ID (LABEL; also ALIAS, ...), ...",
    /// cut past about 16000 bytes with how many more there are.
    std::string accepted() const;

private:
    /// Material index of the class whose label is `label` (trimmed, case
    /// aside), or EMPTY.
    uint32_t find_label(const std::string &label) const;

    std::vector<Material> materials_;
    std::vector<std::vector<std::string>> aliases_;
    // material by id, and by lower-case alias, label, label without commas
    std::unordered_map<int32_t, uint32_t> by_id_;
    std::unordered_map<std::string, uint32_t> by_alias_, by_label_, by_bare_label_;
    /// first part of each label with commas (lower case) -> its most
    /// commas (at most 32)
    std::unordered_map<std::string, size_t> label_heads_;
};

} // namespace sbrt

#endif
