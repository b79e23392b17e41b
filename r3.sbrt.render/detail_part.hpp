/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A render request's level of detail: detail=exact (the stacks
 *            as stored) or coarse (the SBRT's coarse level, stacks_lod, for
 *            frames drawn while the camera moves; issue 49, item 4)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_DETAIL_PART_HPP
#define R3_SBRT_DETAIL_PART_HPP

#include <string>

#include "option_table.hpp"

/// \brief detail=: which level of the model a render draws. No key of its
/// own: RenderSession keeps a level of each detail, every stage cached in
/// its level, so detail= picks the level instead of keying a stage.
struct DetailPart {
    bool coarse = false; ///< detail=coarse asked for
    /// Set by RenderSession::load: fine cells a side per cell of the level
    /// drawn (1: exact), for the messages and the maps' history that say a
    /// frame is coarse. It follows from the model, not from an option.
    int drawn_factor = 1;

    static void define(OptionTable &table);
    void read(const Answers &answers);
    /// "coarse level of detail, 1 cell in N a side (detail=coarse)"
    /// where the frame drawn is coarse, else empty.
    std::string coarse_note() const;
};

#endif
