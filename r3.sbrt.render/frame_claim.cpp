/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   A frame's claim while it is rendered
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "frame_claim.hpp"
#include "request_error.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fcntl.h>
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

/// Whether process `pid` of this host has ended.
bool ended(long pid)
{
    return pid > 0 && kill(pid_t(pid), 0) != 0 && errno == ESRCH;
}

} // namespace

FrameClaim::FrameClaim(const std::string &png, int frame)
{
    if (png.empty())
        return;
    const std::string path = png + ".claim", host = this_host();
    for (int attempt = 0; attempt < 2; ++attempt) {
        const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
        if (fd >= 0) {
            const std::string owner = host + " " + std::to_string(getpid()) + "\n";
            const bool written = write(fd, owner.data(), owner.size()) == ssize_t(owner.size());
            close(fd);
            if (!written) {
                std::remove(path.c_str());
                bad_request(_("Cannot write the claim file <%s> of frame %d: %s"),
                            path.c_str(), frame, std::strerror(errno));
            }
            path_ = path;
            return;
        }
        if (errno != EEXIST) {
            // a folder where claims cannot be made: its PNG cannot be written
            // either, which the PNG's own writing reports
            G_warning(_("Frame %d is rendered without a claim file <%s>: %s"), frame,
                      path.c_str(), std::strerror(errno));
            return;
        }
        std::ifstream in(path);
        std::string owner_host;
        long pid = 0;
        in >> owner_host >> pid;
        if (attempt == 0 && owner_host == host && ended(pid)) {
            std::remove(path.c_str()); // a job of this host was killed on it
            continue;
        }
        bad_request(_("Frame %d <%s> is being rendered by another job (process %ld on "
                      "%s, claim file <%s>): give each job frames of its own (range=), "
                      "or remove the claim file where that job has ended on another "
                      "machine"),
                    frame, png.c_str(), pid, owner_host.empty() ? "?" : owner_host.c_str(),
                    path.c_str());
    }
}

FrameClaim::~FrameClaim()
{
    if (!path_.empty())
        std::remove(path_.c_str());
}
