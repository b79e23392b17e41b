/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   How many lines of a rules file name a class of the model and
 *            how many name none (issue 48, item 12): a rule for an id the
 *            model lacks changes nothing, and is said so, not passed over
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_SUPPORT_RULE_COUNTS_HPP
#define R3_SBRT_SUPPORT_RULE_COUNTS_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/legend_rules.hpp"
#include "model/model.hpp"

/// \brief Lines of a rules file: those that reach a class, those that
/// reach none (the first of them as written, "999" or "5:8").
struct RuleCounts {
    size_t lines = 0;
    size_t unmatched = 0;
    std::string first_unmatched;
};

/// The class ids of `materials` (index 0, EMPTY, left out), sorted.
std::vector<int32_t> class_ids(const std::vector<sbrt::Material> &materials);

/// Category rules: a rule reaches a class when its id, or one of its
/// range low..high, is a class id.
RuleCounts count_label_rules(const std::vector<sbrt::ClassStyle> &rules,
                             const std::vector<int32_t> &ids);

/// Colour rules, by their values in the order of the file: a value reaches
/// a class when it is a class id or a class lies between it and the next
/// value below or above it (the colours between two rules are interpolated).
RuleCounts count_color_rules(const std::vector<double> &values,
                             const std::vector<int32_t> &ids);

#endif
