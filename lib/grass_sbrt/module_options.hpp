/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Options the measuring modules share: the SBRT read, the
 *            probability channels summed, and the number of threads
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MODULE_OPTIONS_HPP
#define SBRT_MODULE_OPTIONS_HPP

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "grass.hpp"

namespace sbrt_grass {

/// `key`=: an existing SBRT, required (a caller may make it optional or
/// multiple); the one definition every module's SBRT option has (the
/// dialogs offer the SBRTs: offer_sbrts_in_dialog, offer_own_sbrts_in_dialog).
Option *define_sbrt_option(const char *key, const char *description);

/// probability=: property channels in %, one or a sum (kans_5+kans_6+
/// kans_7); `label` says what the module makes of it.
Option *define_probability(const char *label);

/// memory= as GRASS defines it (G_OPT_MEMORYMB: MB, default 300), with
/// the module's `description` of what it holds within it.
Option *define_memory(const char *description);
/// Its answer in bytes; a clear fatal error where it is not a positive
/// number of MB.
uint64_t read_memory(const Option *memory);
/// The bytes of memory= text `mb` (MB, at least 1), or 0 where it is not
/// such a number.
uint64_t memory_bytes_of(const char *mb);
/// nprocs=: GRASS's G_OPT_M_NPROCS with GRASS 8.4's meaning, the one
/// definition of every module that uses more than one core: a number of
/// threads, 0 (the default) for all cores, a negative number for all but
/// that many.
Option *define_nprocs();
/// Its answer as a number of threads: at least 1, all cores for 0, all
/// but -n for a negative n (at least 1 where that leaves none).
unsigned read_nprocs(const Option *nprocs);
/// The same for the option's answer as text (a view server's request word).
unsigned read_nprocs(const std::string &answer);

/// The east,north pairs of a coordinates= option (G_OPT_M_COORDS with
/// multiple answers), in order; none where it has no answer.
std::vector<glm::dvec2> read_coordinate_pairs(const Option *coordinates);

} // namespace sbrt_grass

#endif
