/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT directory read as untrusted input (it may lie in
 *            another user's mapset): its members are opened relative to
 *            the directory, never through a symbolic link, never waiting
 *            on a FIFO, and only when they are regular files, as systemd's
 *            chase() (src/basic/chase.c) opens paths it does not trust
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MEMBER_DIR_HPP
#define SBRT_MEMBER_DIR_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sbrt {

/// \brief An open file descriptor, closed with its owner (move-only).
class FileDescriptor {
public:
    FileDescriptor() = default;
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor();
    FileDescriptor(FileDescriptor &&other) noexcept : fd_(other.release()) {}
    FileDescriptor &operator=(FileDescriptor &&other) noexcept;
    FileDescriptor(const FileDescriptor &) = delete;
    FileDescriptor &operator=(const FileDescriptor &) = delete;

    int get() const { return fd_; }
    bool is_open() const { return fd_ >= 0; }
    /// Gives up ownership: the caller closes the descriptor.
    int release();

private:
    int fd_ = -1;
};

/// \brief A directory whose members are regular files, nothing else (the
/// SBRT format has no subdirectories): each member is checked with
/// fstatat(AT_SYMLINK_NOFOLLOW), opened with openat(O_NOFOLLOW |
/// O_NONBLOCK) and checked again with fstat on what was opened, so neither
/// a symbolic link nor a FIFO, device or socket swapped in between is read.
/// Every refusal is an sbrt::Error naming the member and what it is.
class MemberDirectory {
public:
    /// Opens directory `path`; its last component must be the directory
    /// itself, not a symbolic link to one.
    explicit MemberDirectory(std::string path);

    const std::string &path() const { return path_; }
    int fd() const { return dir_.get(); }
    /// `path()/name`, for messages.
    std::string member_path(const std::string &name) const;

    /// Member `name` open for reading; throws where it is missing, is not
    /// a regular file or cannot be opened.
    FileDescriptor open_regular(const std::string &name) const;
    /// As open_regular, but none where `name` does not exist.
    std::optional<FileDescriptor> open_regular_if_present(const std::string &name) const;
    /// Every entry but "." and "..", sorted (not checked: open each).
    std::vector<std::string> member_names() const;

private:
    std::string path_;
    FileDescriptor dir_;
};

/// A regular file `path` open for reading, with the checks of
/// MemberDirectory::open_regular on its last component.
FileDescriptor open_regular_file(const std::string &path);

/// Size in bytes of the regular file open as `fd`; `what` names it.
uint64_t regular_file_size(const FileDescriptor &fd, const std::string &what);

/// All bytes of the regular file open as `fd`; `what` names it.
std::vector<uint8_t> read_all(const FileDescriptor &fd, const std::string &what);

} // namespace sbrt

#endif
