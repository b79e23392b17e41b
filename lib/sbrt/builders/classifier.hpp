/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Turns cell values into class ids: integers as they are, or
 *            value ranges through recode-style rules; never rounds silently
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CLASSIFIER_HPP
#define SBRT_CLASSIFIER_HPP

#include <istream>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

/// \brief One rule "low:high:class[:label]"; the range includes both ends.
struct ClassRule {
    double low, high;
    int32_t id;
    std::string label;
};

/// \brief Value -> class id. Without rules a value must be an integer within
/// the 32-bit range; with rules a value no rule covers becomes empty.
class Classifier {
public:
    Classifier() = default;
    explicit Classifier(std::vector<ClassRule> rules);

    /// Parses rules from a stream ('#' comments, blank lines, "end" stops);
    /// `source` names the stream in error messages.
    static Classifier parse(std::istream &in, const std::string &source);

    /// Class id of `value` (NaN = null -> NULL_CLASS). Throws sbrt::Error
    /// for a non-integer or out-of-range value when there are no rules.
    int32_t classify(double value)
    {
        if (value != value)
            return NULL_CLASS;
        if (rules_.empty())
            return integer_class(value);
        return ruled_class(value);
    }

    bool has_rules() const { return !rules_.empty(); }
    const std::vector<ClassRule> &rules() const { return rules_; }
    /// Values that no rule covered (they became empty).
    uint64_t unmatched() const { return unmatched_; }

private:
    int32_t integer_class(double value) const;
    int32_t ruled_class(double value);

    std::vector<ClassRule> rules_;
    uint64_t unmatched_ = 0;
};

} // namespace sbrt

#endif
