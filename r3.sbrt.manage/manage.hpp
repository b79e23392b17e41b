/****************************************************************************
 * MODULE:    r3.sbrt.manage
 * PURPOSE:   The operations the module offers, one file each, with GRASS's
 *            rules (those of g.list, g.copy, g.rename, g.remove in 8.2)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef R3_SBRT_MANAGE_HPP
#define R3_SBRT_MANAGE_HPP

#include <string>
#include <vector>

#include "grass.hpp"
#include "output_format.hpp"

/// How messages name an SBRT: the description of the ELEMENT_LIST line
/// (sbrt:sbrt:SBRT model:SBRT model(s)), so that r3.sbrt.manage and the
/// g.* modules with that line say the same.
constexpr const char *SBRT_DESCRIPTION = "SBRT model";

/// The mapsets that mapset= names ('.' current, '*' all of the location),
/// or the search path without it; fatal error for a name that is not one
/// of a mapset of the current location.
std::vector<std::string> mapsets_to_list(const Option *mapset);

/// Prints the SBRTs of `mapsets` sorted as g.list sorts. plain: one a
/// line, the name alone, with @mapset where `qualified` or where the same
/// name is in several of the mapsets; json: a list of objects with name,
/// mapset and fullname (as g.list of GRASS 8.5 writes them); csv: those
/// columns parted by `separator`, with a header.
void print_sbrts(const std::vector<std::string> &mapsets, bool qualified,
                 sbrt_grass::OutputFormat format, char separator);

/// copy=from,to[,from,to...] into the current mapset, as g.copy.
void copy_sbrts(const Option *copy, bool overwrite);

/// rename=old,new[,old,new...] in the current mapset, as g.rename.
void rename_sbrts(const Option *rename, bool overwrite);

/// remove=name[,name...] from the current mapset, as g.remove: only
/// printed unless `force`.
void remove_sbrts(const Option *remove, bool force);

#endif
