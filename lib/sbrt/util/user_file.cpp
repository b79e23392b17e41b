/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A small file a user names, read whole: regular and bounded
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/user_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "util/error.hpp"

namespace sbrt {

const char *file_kind(unsigned mode)
{
    if (S_ISLNK(mode))
        return "a symbolic link";
    if (S_ISDIR(mode))
        return "a directory";
    if (S_ISFIFO(mode))
        return "a FIFO (named pipe)";
    if (S_ISSOCK(mode))
        return "a socket";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    return "not a regular file";
}

std::string read_to_end(int fd, uint64_t max_bytes, const std::string &what)
{
    std::string text;
    char buffer[65536];
    for (;;) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            fail(what, ": cannot read: ", std::strerror(errno));
        if (n == 0)
            return text;
        if (text.size() + uint64_t(n) > max_bytes)
            fail(what, ": more than ", max_bytes, " bytes, more than such a file may hold");
        text.append(buffer, size_t(n));
    }
}

std::string read_user_file(const std::string &path, uint64_t max_bytes,
                           const std::string &what)
{
    // O_NONBLOCK: opening a FIFO does not wait for a writer (it is refused
    // below); a regular file read in non-blocking mode reads as usual
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
        fail(what, ": cannot open: ", std::strerror(errno));
    struct Closer {
        int fd;
        ~Closer() { close(fd); }
    } const closer{fd};
    struct stat st;
    if (fstat(fd, &st) != 0)
        fail(what, ": cannot read: ", std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        fail(what, ": ", file_kind(st.st_mode), ", not a regular file");
    if (uint64_t(st.st_size) > max_bytes)
        fail(what, ": ", uint64_t(st.st_size), " bytes, more than such a file may hold (",
             max_bytes, ")");
    return read_to_end(fd, max_bytes, what);
}

} // namespace sbrt
