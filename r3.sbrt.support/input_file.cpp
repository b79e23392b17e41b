/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Rules files read whole, bounded, regular files only
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "input_file.hpp"

#include <unistd.h>

#include <cstring>

#include "grass.hpp"
#include "util/error.hpp"
#include "util/user_file.hpp"

std::string read_rules_file(const char *key, const char *file)
{
    const std::string what = std::string(key) + "=" + file;
    try {
        if (std::strcmp(file, "-") == 0)
            return sbrt::read_to_end(STDIN_FILENO, MAX_RULES_BYTES, what);
        // a link is followed, as for any file named on the command line; a
        // FIFO, a device or a directory is refused at once
        return sbrt::read_user_file(file, MAX_RULES_BYTES, what);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("%s; give a file of rules (at most %zu MiB), or '-' to read them "
                        "from standard input"),
                      e.what(), MAX_RULES_BYTES >> 20);
    }
}
