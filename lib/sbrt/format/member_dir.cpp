/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Opening the members of an untrusted directory: no symbolic
 *            links, no FIFOs or devices, regular files only
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/member_dir.hpp"

#include <cerrno>
#include <cstring>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

#include "util/error.hpp"
#include "util/user_file.hpp"

namespace sbrt {

namespace {

[[noreturn]] void refuse(const std::string &what, mode_t mode)
{
    fail(what, ": ", file_kind(mode),
         ", not a regular file (an SBRT holds regular files only)");
}

/// A member name is one directory entry: no path, no "." or "..".
void require_member_name(const std::string &name, const std::string &what)
{
    if (name.empty() || name == "." || name == ".." ||
        name.find('/') != std::string::npos)
        fail(what, ": not the name of a file in the directory");
}

/// Opens `name` relative to `dir` (AT_FDCWD for a path) as described in
/// the header; -1 with errno ENOENT where nothing is there.
int open_checked(int dir, const std::string &name, const std::string &what)
{
    // look first, without opening: opening a device may have effects
    struct stat before;
    if (fstatat(dir, name.c_str(), &before, AT_SYMLINK_NOFOLLOW) != 0) {
        if (errno == ENOENT)
            return -1;
        fail(what, ": cannot read: ", std::strerror(errno));
    }
    if (!S_ISREG(before.st_mode))
        refuse(what, before.st_mode);
    // O_NONBLOCK: a FIFO swapped in since is opened without waiting for a
    // writer, then refused below; O_NOFOLLOW: a link swapped in, ELOOP
    const int fd = openat(dir, name.c_str(),
                          O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        if (errno == ELOOP)
            refuse(what, S_IFLNK);
        fail(what, ": cannot open: ", std::strerror(errno));
    }
    FileDescriptor file(fd);
    struct stat opened;
    if (fstat(fd, &opened) != 0)
        fail(what, ": cannot read: ", std::strerror(errno));
    if (!S_ISREG(opened.st_mode))
        refuse(what, opened.st_mode);
    // a regular file never blocks; reads behave as without the flag
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return file.release();
}

} // namespace

FileDescriptor::~FileDescriptor()
{
    if (fd_ >= 0)
        close(fd_);
}

FileDescriptor &FileDescriptor::operator=(FileDescriptor &&other) noexcept
{
    if (this != &other) {
        if (fd_ >= 0)
            close(fd_);
        fd_ = other.release();
    }
    return *this;
}

int FileDescriptor::release()
{
    const int fd = fd_;
    fd_ = -1;
    return fd;
}

MemberDirectory::MemberDirectory(std::string path) : path_(std::move(path))
{
    const int fd = open(path_.c_str(),
                        O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        const int error = errno;
        struct stat st;
        if (lstat(path_.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
            fail(path_, ": a symbolic link, not a directory; an SBRT is a "
                 "directory of its own (copy the SBRT instead of linking it)");
        fail(path_, ": cannot open the directory: ", std::strerror(error));
    }
    dir_ = FileDescriptor(fd);
}

std::string MemberDirectory::member_path(const std::string &name) const
{
    return path_ + "/" + name;
}

FileDescriptor MemberDirectory::open_regular(const std::string &name) const
{
    std::optional<FileDescriptor> file = open_regular_if_present(name);
    if (!file)
        fail(member_path(name), ": missing");
    return std::move(*file);
}

std::optional<FileDescriptor>
MemberDirectory::open_regular_if_present(const std::string &name) const
{
    const std::string what = member_path(name);
    require_member_name(name, what);
    const int fd = open_checked(dir_.get(), name, what);
    if (fd < 0)
        return std::nullopt;
    return FileDescriptor(fd);
}

std::vector<std::string> MemberDirectory::member_names() const
{
    // a directory stream of its own: readdir moves the descriptor's offset
    const int fd = openat(dir_.get(), ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    DIR *dir = fd < 0 ? nullptr : fdopendir(fd);
    if (!dir) {
        const int error = errno;
        if (fd >= 0)
            close(fd);
        fail(path_, ": cannot list: ", std::strerror(error));
    }
    std::vector<std::string> names;
    errno = 0;
    while (const dirent *entry = readdir(dir)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..")
            names.push_back(name);
        errno = 0;
    }
    const int error = errno;
    closedir(dir);
    if (error != 0)
        fail(path_, ": cannot list: ", std::strerror(error));
    std::sort(names.begin(), names.end());
    return names;
}

FileDescriptor open_regular_file(const std::string &path)
{
    const int fd = open_checked(AT_FDCWD, path, path);
    if (fd < 0)
        fail(path, ": cannot open: ", std::strerror(ENOENT));
    return FileDescriptor(fd);
}

uint64_t regular_file_size(const FileDescriptor &fd, const std::string &what)
{
    struct stat st;
    if (fstat(fd.get(), &st) != 0)
        fail(what, ": cannot read: ", std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        refuse(what, st.st_mode);
    return uint64_t(st.st_size);
}

std::vector<uint8_t> read_all(const FileDescriptor &fd, const std::string &what)
{
    std::vector<uint8_t> bytes(size_t(regular_file_size(fd, what)));
    size_t got = 0;
    while (got < bytes.size()) {
        const ssize_t n = pread(fd.get(), bytes.data() + got, bytes.size() - got, off_t(got));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            fail(what, ": cannot read: ", std::strerror(errno));
        if (n == 0)
            break;
        got += size_t(n);
    }
    if (got != bytes.size())
        fail(what, ": read ", got, " of ", bytes.size(), " bytes");
    return bytes;
}

} // namespace sbrt
