/****************************************************************************
 * MODULE:    r3.sbrt.support
 * PURPOSE:   Rules files read whole, bounded, regular files only
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "input_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grass.hpp"
#include "format/member_dir.hpp"

namespace {

const char *kind_of(mode_t mode)
{
    if (S_ISDIR(mode))
        return _("a directory");
    if (S_ISFIFO(mode))
        return _("a FIFO (named pipe)");
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return _("a device");
    if (S_ISSOCK(mode))
        return _("a socket");
    return _("not a regular file");
}

/// Appends what `fd` holds up to its end, at most MAX_RULES_BYTES in all.
void read_to_end(int fd, const char *key, const char *file, std::string &text)
{
    char buffer[65536];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            G_fatal_error(_("%s=%s: cannot read: %s"), key, file, std::strerror(errno));
        if (n == 0)
            return;
        if (text.size() + size_t(n) > MAX_RULES_BYTES)
            G_fatal_error(_("%s=%s: more than the %zu MiB of rules read; split the file"),
                          key, file, MAX_RULES_BYTES >> 20);
        text.append(buffer, size_t(n));
    }
}

} // namespace

std::string read_rules_file(const char *key, const char *file)
{
    std::string text;
    if (std::strcmp(file, "-") == 0) {
        read_to_end(STDIN_FILENO, key, file, text);
        return text;
    }
    // O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused
    // below); a link is followed, as for any file named on the command line
    const int fd = open(file, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
        G_fatal_error(_("%s=%s: unable to open this file: %s"), key, file,
                      std::strerror(errno));
    const sbrt::FileDescriptor owner(fd);
    struct stat st;
    if (fstat(fd, &st) != 0)
        G_fatal_error(_("%s=%s: cannot read: %s"), key, file, std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        G_fatal_error(_("%s=%s: %s, not a regular file; give a file of rules, or '-' "
                        "to read them from standard input"),
                      key, file, kind_of(st.st_mode));
    if (uint64_t(st.st_size) > MAX_RULES_BYTES)
        G_fatal_error(_("%s=%s: more than the %zu MiB of rules read (%.1f MiB); split "
                        "the file"),
                      key, file, MAX_RULES_BYTES >> 20, double(st.st_size) / (1 << 20));
    // a regular file read in non-blocking mode reads as usual
    text.reserve(size_t(st.st_size));
    read_to_end(fd, key, file, text);
    return text;
}
