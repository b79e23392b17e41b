/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The writers' lock of an SBRT: flock(2) on a hidden sibling,
 *            taken with a bounded wait
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/sbrt_lock.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <thread>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// The lock file open for locking: created where missing, never through a
/// symbolic link, never a FIFO or device (O_NONBLOCK: opening one does
/// not wait). Open for writing: on NFS flock(2) is an fcntl lock, whose
/// exclusive form needs a file open for writing (flock(2), NOTES).
FileDescriptor open_lock_file(const std::string &path)
{
    const int fd = open(path.c_str(),
                        O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY,
                        0664);
    if (fd < 0) {
        if (errno == ELOOP)
            fail(path, ": a symbolic link, not a lock file; remove it");
        fail(path, ": cannot open the lock file: ", std::strerror(errno));
    }
    FileDescriptor file(fd);
    struct stat st;
    if (fstat(fd, &st) != 0)
        fail(path, ": cannot read the lock file: ", std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        fail(path, ": not a regular file, so not a lock file; remove it");
    return file;
}

} // namespace

std::string SbrtLock::lock_path(const std::string &directory)
{
    std::string path = directory;
    while (path.size() > 1 && path.back() == '/')
        path.pop_back();
    const auto slash = path.find_last_of('/');
    const std::string parent = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    if (base.empty() || base == "." || base == ".." || base == "/")
        fail("SbrtLock: <", directory, "> names no SBRT directory");
    return parent + "." + base + ".lock";
}

SbrtLock::SbrtLock(const std::string &directory, std::chrono::milliseconds wait)
{
    using Clock = std::chrono::steady_clock;
    const std::string path = lock_path(directory);
    FileDescriptor file = open_lock_file(path);
    const Clock::time_point deadline = Clock::now() + wait;
    // polling with LOCK_NB keeps the wait bounded without signals; the
    // pause grows to 50 ms, short beside a rewrite of the legend
    std::chrono::milliseconds pause(2);
    for (;;) {
        if (flock(file.get(), LOCK_EX | LOCK_NB) == 0)
            break;
        if (errno == EINTR)
            continue;
        if (errno != EWOULDBLOCK)
            fail(path, ": cannot lock: ", std::strerror(errno));
        const Clock::time_point now = Clock::now();
        if (now >= deadline)
            fail(directory, ": another process is changing it (waited ",
                 std::chrono::duration<double>(wait).count(), " s for its lock ", path,
                 "); try again when it has finished");
        std::this_thread::sleep_for(
            std::min<Clock::duration>(pause, deadline - now));
        pause = std::min(pause * 2, std::chrono::milliseconds(50));
    }
    file_ = std::move(file);
}

} // namespace sbrt
