/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's property view: the channels shown, their colours,
 *            the uncertainty fade, the value map (the session's property
 *            stage keys on it), and select= (its own part: the selection
 *            stage's key)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_PROPERTY_PART_HPP
#define R3_SBRT_PROPERTY_PART_HPP

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "option_table.hpp"

/// \brief property=, property_color=, fade=, fade_range=, value= (an
/// output: not in the key).
struct PropertyPart {
    std::vector<std::string> property;      ///< channels to show, summed
    std::string property_color = "viridis"; ///< colour table or rules file
    std::string fade;                       ///< fade=: an uncertainty channel
    std::optional<std::array<double, 2>> fade_range; ///< its values of no and full grey
    std::string value;                      ///< value=: the property at the hit

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
    /// property= as given ("kans_5+kans_6").
    std::string property_title() const;

private:
    void read_fade(const Answers &answers);
};

/// \brief select=: only the voxels whose property meets a condition.
struct SelectionPart {
    std::string select;

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const { return select; }
};

#endif
