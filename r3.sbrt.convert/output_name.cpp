/****************************************************************************
 * MODULE:    r3.sbrt.convert
 * PURPOSE:   A new map's name checked before any work: legal in GRASS and
 *            short enough for the file system
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "convert.hpp"

#include <cstring>

#include "grass.hpp"

namespace {

/// A file name's limit (NAME_MAX of Linux file systems).
constexpr size_t NAME_MAX_BYTES = 255;
/// An SBRT is written to a hidden sibling `.name.tmp.PID` (and a previous
/// one kept as `.name.old.PID` while it is swapped): 6 bytes and a
/// process id of up to 10 digits more than the name.
constexpr size_t SIBLING_EXTRA = 1 + 5 + 10;

} // namespace

void check_output_name(const char *name, bool sbrt)
{
    const char *what = sbrt ? _("SBRT") : _("3D raster map");
    const size_t limit = sbrt ? NAME_MAX_BYTES - SIBLING_EXTRA : NAME_MAX_BYTES;
    const size_t length = std::strlen(name);
    if (length > limit)
        G_fatal_error(_("The %s name in output= has %zu characters; at most %zu are "
                        "allowed. Give a shorter name"),
                      what, length, limit);
    if (G_legal_filename(name) != 1)
        G_fatal_error(_("<%s> is an illegal %s name"), name, what);
    // the whole path in the mapset must fit GRASS's path buffers
    char path[GPATH_MAX];
    G_file_name(path, sbrt ? "sbrt" : "grid3", "", G_mapset());
    if (std::strlen(path) + length + SIBLING_EXTRA + 16 >= GPATH_MAX)
        G_fatal_error(_("The path of %s <%s> in this mapset would be longer than %d "
                        "characters; give a shorter name"),
                      what, name, GPATH_MAX);
}
