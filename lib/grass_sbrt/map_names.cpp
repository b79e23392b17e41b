/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   A new map's name checked before any work: legal in GRASS and
 *            short enough for the file system
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "map_names.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstring>

#include "grass.hpp"
#include "util/error.hpp"

namespace {

/// A file name's limit (NAME_MAX of Linux file systems).
constexpr size_t NAME_MAX_BYTES = 255;
/// An SBRT is written to a hidden sibling `.name.tmp.PID` (and a previous
/// one kept as `.name.old.PID` while it is swapped): 6 bytes and a
/// process id of up to 10 digits more than the name.
constexpr size_t SIBLING_EXTRA = 1 + 5 + 10;

/// The message of `format` (printf) as an sbrt::Error.
[[noreturn]] void fail_with(const char *format, ...) __attribute__((format(printf, 1, 2)));
void fail_with(const char *format, ...)
{
    char text[1024];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof text, format, args);
    va_end(args);
    throw sbrt::Error(text);
}

} // namespace

namespace sbrt_grass {

void check_new_name(const char *name, bool sbrt, const char *option)
{
    const char *what = sbrt ? _("SBRT") : _("3D raster map");
    const size_t limit = sbrt ? NAME_MAX_BYTES - SIBLING_EXTRA : NAME_MAX_BYTES;
    const size_t length = std::strlen(name);
    if (length > limit)
        fail_with(_("The %s name in %s= has %zu characters; at most %zu are allowed. "
                    "Give a shorter name"),
                  what, option, length, limit);
    if (G_legal_filename(name) != 1)
        fail_with(_("%s=%s: an illegal %s name"), option, name, what);
    // the whole path in the mapset must fit GRASS's path buffers
    char path[GPATH_MAX];
    G_file_name(path, sbrt ? "sbrt" : "grid3", "", G_mapset());
    if (std::strlen(path) + length + SIBLING_EXTRA + 16 >= GPATH_MAX)
        fail_with(_("The path of %s <%s> in this mapset would be longer than %d "
                    "characters; give a shorter name"),
                  what, name, GPATH_MAX);
}

} // namespace sbrt_grass
