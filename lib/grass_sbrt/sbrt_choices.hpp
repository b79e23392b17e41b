/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An option naming an existing SBRT offered as a drop-down list
 *            in the modules' GUI dialogs
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CHOICES_HPP
#define SBRT_CHOICES_HPP

#include "grass.hpp"

namespace sbrt_grass {

/// When the GUI asks for the module's interface (--interface-description),
/// lists the SBRTs of the search path as `option`'s values (the plain
/// names the search path finds unambiguously, then every name@mapset): the
/// dialog shows them in an editable drop-down. pygrass checks values
/// against this list too, so a script passes one of these names. GRASS 8.2's GUI has a
/// picker for its built-in elements only, whatever gisprompt says ("Not
/// selectable element"), so the gisprompt is dropped there. Any other run
/// keeps the option free: G_parser would check an answer against the list
/// and complete a unique prefix (input=geo becoming geology), where a user
/// must get the map named or an error.
void offer_sbrts_in_dialog(Option *option, int argc, char *argv[]);
/// The same with only the current mapset's SBRTs, by their plain names
/// (what an option that changes SBRTs, such as remove=, may name; a
/// multiple option shows a check box for each).
void offer_own_sbrts_in_dialog(Option *option, int argc, char *argv[]);

} // namespace sbrt_grass

#endif
