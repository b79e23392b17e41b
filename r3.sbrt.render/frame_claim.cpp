/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A frame's claim while it is rendered
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frame_claim.hpp"
#include "request_error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

extern "C" {
#include <grass/gis.h>
#include <grass/glocale.h>
}

namespace {

std::string this_host()
{
    char name[256] = {};
    if (gethostname(name, sizeof name - 1) != 0)
        return "localhost";
    return name;
}

/// What a claim file says of its job: "host pid".
std::string owner_of(int fd)
{
    char text[300] = {};
    const ssize_t n = pread(fd, text, sizeof text - 1, 0);
    std::string owner(text, n > 0 ? size_t(n) : 0);
    while (!owner.empty() && (owner.back() == '\n' || owner.back() == ' '))
        owner.pop_back();
    return owner.empty() ? "a job that has not written its name yet" : owner;
}

} // namespace

FrameClaim::FrameClaim(const std::string &png, int frame)
{
    if (png.empty())
        return;
    const std::string path = png + ".claim";
    // the claim is the lock on the file: the kernel lets it go with the
    // process, so a killed job's claim lapses by itself
    for (;;) {
        const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0) {
            // a folder where claims cannot be made: its PNG cannot be
            // written either, which the PNG's own writing reports
            G_warning(_("Frame %d is rendered without a claim file <%s>: %s"), frame,
                      path.c_str(), std::strerror(errno));
            return;
        }
        if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const std::string owner = owner_of(fd);
            close(fd);
            bad_request(_("Frame %d <%s> is being rendered by another job (%s; claim "
                          "file <%s>): give each job frames of its own (range=)"),
                        frame, png.c_str(), owner.c_str(), path.c_str());
        }
        // still the file at the path (not one its last owner removed)?
        struct stat held, named;
        if (fstat(fd, &held) == 0 && stat(path.c_str(), &named) == 0 &&
            held.st_ino == named.st_ino && held.st_dev == named.st_dev) {
            const std::string owner = this_host() + " process " + std::to_string(getpid()) + "\n";
            if (ftruncate(fd, 0) != 0 || pwrite(fd, owner.data(), owner.size(), 0) < 0)
                G_warning(_("Cannot write the claim file <%s>: %s"), path.c_str(),
                          std::strerror(errno));
            fd_ = fd;
            path_ = path;
            return;
        }
        close(fd); // removed meanwhile: claim the new one
    }
}

FrameClaim::~FrameClaim()
{
    if (path_.empty())
        return;
    std::remove(path_.c_str()); // while the lock is held: the file is ours
    close(fd_);
}
