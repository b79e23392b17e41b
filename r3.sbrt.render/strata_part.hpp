/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's strata: hidden and translucent classes (part
 *            of the prepared scene's key)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_STRATA_PART_HPP
#define R3_SBRT_STRATA_PART_HPP

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "option_table.hpp"

/// \brief hide=, opacity=, opacity_length=.
struct StrataPart {
    std::vector<std::string> hide;                       ///< class ids or labels
    std::vector<std::pair<std::string, double>> opacity; ///< class, alpha
    std::optional<double> opacity_length;                ///< map units (default a cell)

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
};

#endif
