/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   detail=: the level of detail a render draws
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "detail_part.hpp"

void DetailPart::define(OptionTable &table)
{
    table.define_choice(
        "detail", _("Level of detail of the model"), _("Settings"), "exact", "exact,coarse",
        _("exact;the stacks as stored: every cell, exact;"
          "coarse;the coarse level stored beside them (SBRTs of 512 x 512 cells "
          "or more, r3.sbrt.convert writes it), a frame for moving views: each "
          "cell the exact stack of one cell in N x N, never exact"));
}

void DetailPart::read(const Answers &a)
{
    coarse = a.text("detail", "exact") == "coarse";
    drawn_factor = 1;
}

std::string DetailPart::coarse_note() const
{
    if (drawn_factor <= 1)
        return {};
    return "coarse level of detail, 1 cell in " + std::to_string(drawn_factor) +
           " a side (detail=coarse), not exact";
}
