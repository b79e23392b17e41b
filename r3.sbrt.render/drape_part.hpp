/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's drape: texture maps on the terrain (the
 *            session's drape stage keys on it)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_DRAPE_PART_HPP
#define R3_SBRT_DRAPE_PART_HPP

#include <string>
#include <vector>

#include "option_table.hpp"

/// \brief texture=, texture_blend=.
struct DrapePart {
    std::vector<std::string> texture; ///< one map, or red,green,blue
    double texture_blend = 1;

    static void define(OptionTable &table);
    void read(const Answers &answers);
    std::string key() const;
};

#endif
