/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   output= written into a temporary sibling, renamed when whole
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "report_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "grass.hpp"
#include "module_errors.hpp"

namespace sbrt_grass {

ReportFile::ReportFile(std::string name) : name_(std::move(name))
{
    if (name_.empty() || name_ == "-")
        return;
    std::string pattern = name_ + ".partXXXXXX";
    std::vector<char> path(pattern.begin(), pattern.end());
    path.push_back('\0');
    const int fd = mkstemp(path.data());
    if (fd < 0)
        fail_with(_("output=%s: cannot write the file (%s)"), name_.c_str(),
                  std::strerror(errno));
    temporary_ = path.data();
    // the mode a plain fopen would give (mkstemp makes it 0600)
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    file_ = fdopen(fd, "w");
    if (!file_) {
        const int error = errno;
        close(fd);
        std::remove(temporary_.c_str());
        fail_with(_("output=%s: cannot write the file (%s)"), name_.c_str(),
                  std::strerror(error));
    }
}

ReportFile::~ReportFile()
{
    if (!file_)
        return;
    std::fclose(file_);
    std::remove(temporary_.c_str());
}

void ReportFile::commit()
{
    if (!file_)
        return;
    errno = 0;
    const bool failed = std::fflush(file_) != 0 || std::ferror(file_) != 0;
    const int error = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (failed || !closed || std::rename(temporary_.c_str(), name_.c_str()) != 0) {
        const int why = error ? error : errno;
        std::remove(temporary_.c_str());
        fail_with(_("output=%s: writing the file failed (%s)"), name_.c_str(),
                  why ? std::strerror(why) : "error while writing");
    }
}

} // namespace sbrt_grass
