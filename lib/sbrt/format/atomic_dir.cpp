/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Atomic replacement of a directory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/atomic_dir.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "format/member_dir.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

std::string parent_of(const std::string &path)
{
    const auto slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

/// `.name.tag.` of target `dir/name`: the start of its hidden siblings'
/// names, which end in the writer's process id.
std::string sibling_prefix(const std::string &target, const char *tag)
{
    const auto slash = target.find_last_of('/');
    const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
    return "." + base + "." + tag + ".";
}

std::string sibling(const std::string &target, const char *tag)
{
    return parent_of(target) + "/" + sibling_prefix(target, tag) + std::to_string(getpid());
}

void sync_path(const std::string &path)
{
    const int fd = open(path.c_str(), O_RDONLY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

/// renameat2(RENAME_EXCHANGE): swaps two paths in one step (Linux >= 3.15).
bool exchange(const std::string &a, const std::string &b)
{
#ifdef SYS_renameat2
    const unsigned int rename_exchange = 1u << 1;
    return syscall(SYS_renameat2, AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(),
                   rename_exchange) == 0;
#else
    (void)a;
    (void)b;
    return false;
#endif
}

/// `name` is one entry of a directory, so that a file of the temporary
/// directory stays in it.
void require_entry_name(const std::string &name, const std::string &dir)
{
    if (name.empty() || name == "." || name == ".." ||
        name.find('/') != std::string::npos)
        fail("AtomicDirectory: <", name, "> is not a file name in ", dir);
}

/// A new file of the temporary directory, opened for writing; never
/// through a symbolic link.
FileDescriptor create_entry(const std::string &path)
{
    const int fd = open(path.c_str(),
                        O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0)
        fail("AtomicDirectory: cannot create ", path, ": ", std::strerror(errno));
    return FileDescriptor(fd);
}

/// Writes all `size` bytes of `data` to `fd`.
void write_all(int fd, const uint8_t *data, size_t size, const std::string &path)
{
    while (size > 0) {
        const ssize_t n = write(fd, data, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            fail("AtomicDirectory: cannot write ", path, ": ",
                 n < 0 ? std::strerror(errno) : "nothing written");
        data += n;
        size -= size_t(n);
    }
}

/// Syncs the file open as `fd` and closes it.
void finish_entry(FileDescriptor file, const std::string &path)
{
    const bool synced = fsync(file.get()) == 0;
    const int error = errno;
    const bool closed = close(file.release()) == 0;
    if (!synced || !closed)
        fail("AtomicDirectory: cannot write ", path, ": ",
             std::strerror(synced ? errno : error));
}

/// Whether nothing in `dir` (the directory and its files) changed for
/// an hour: a writer that still runs, even on another host sharing the
/// database, writes into its temporary all the time.
bool untouched_for_an_hour(const std::filesystem::path &dir)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const auto limit = fs::file_time_type::clock::now() - std::chrono::hours(1);
    if (fs::last_write_time(dir, ec) > limit || ec)
        return false;
    for (const auto &entry : fs::directory_iterator(dir, ec))
        if (fs::last_write_time(entry.path(), ec) > limit || ec)
            return false;
    return !ec;
}

/// Removes what killed writers of `target` left: hidden siblings
/// `.name.tmp.PID` of processes that no longer run here, untouched for an
/// hour. `.name.old.PID` (a previous version, where a kill came between
/// the two renames of commit's fallback) is left for a person to restore.
void sweep_stale_temporaries(const std::string &target)
{
    const std::string prefix = sibling_prefix(target, "tmp");
    std::error_code ec;
    for (const auto &entry : std::filesystem::directory_iterator(parent_of(target), ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0)
            continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
            continue;
        const pid_t pid = pid_t(std::stol(digits));
        if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH &&
            untouched_for_an_hour(entry.path()))
            remove_tree(entry.path().string());
    }
}

} // namespace

std::string stage_other_members(const MemberDirectory &dir, AtomicDirectory &out,
                                const std::vector<std::string> &replaced)
{
    std::string hist;
    for (const std::string &name : dir.member_names()) {
        if (std::find(replaced.begin(), replaced.end(), name) != replaced.end())
            continue;
        const FileDescriptor member = dir.open_regular(name); // no links, no FIFOs
        if (name == "hist") {
            const std::vector<uint8_t> bytes = read_all(member, dir.member_path(name));
            hist.assign(bytes.begin(), bytes.end());
            continue;
        }
        if (linkat(dir.fd(), name.c_str(), AT_FDCWD, out.file_path(name).c_str(), 0) != 0)
            out.copy_file(name, member, dir.member_path(name));
    }
    return hist;
}

bool remove_tree(const std::string &path)
{
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
    return !ec;
}

AtomicDirectory::AtomicDirectory(std::string target)
    : target_(std::move(target)), temp_(sibling(target_, "tmp"))
{
    sweep_stale_temporaries(target_);
    remove_tree(temp_);
    std::error_code ec;
    std::filesystem::create_directories(parent_of(target_), ec);
    if (mkdir(temp_.c_str(), 0755) != 0)
        fail("AtomicDirectory: cannot create ", temp_, ": ",
             std::strerror(errno));
}

AtomicDirectory::~AtomicDirectory()
{
    if (!committed_)
        remove_tree(temp_);
}

void AtomicDirectory::write_file(const std::string &name,
                                 const std::vector<uint8_t> &bytes)
{
    require_entry_name(name, temp_);
    const std::string path = file_path(name);
    FileDescriptor file = create_entry(path);
    write_all(file.get(), bytes.data(), bytes.size(), path);
    finish_entry(std::move(file), path);
}

void AtomicDirectory::write_file(const std::string &name,
                                 const std::string &text)
{
    write_file(name, std::vector<uint8_t>(text.begin(), text.end()));
}

void AtomicDirectory::copy_file(const std::string &name,
                                const FileDescriptor &source,
                                const std::string &what)
{
    require_entry_name(name, temp_);
    const std::string path = file_path(name);
    FileDescriptor file = create_entry(path);
    const uint64_t size = regular_file_size(source, what);
    // in the kernel where it can (copy_file_range, Linux 4.5), else read
    // and write; from offset 0 whatever the source's position
    loff_t in = 0;
    while (uint64_t(in) < size) {
        const ssize_t n = copy_file_range(source.get(), &in, file.get(), nullptr,
                                          size_t(size - uint64_t(in)), 0);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break; // not between these file systems: the loop below
    }
    std::vector<uint8_t> buffer(size_t(1) << 20);
    while (uint64_t(in) < size) {
        const ssize_t n = pread(source.get(), buffer.data(), buffer.size(), in);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            fail("AtomicDirectory: cannot read ", what, " at byte ", in, ": ",
                 n < 0 ? std::strerror(errno) : "the file ended");
        write_all(file.get(), buffer.data(), size_t(n), path);
        in += n;
    }
    finish_entry(std::move(file), path);
}

void AtomicDirectory::commit()
{
    sync_path(temp_);
    replace_directory(temp_, target_);
    committed_ = true;
}

void replace_directory(const std::string &from, const std::string &target)
{
    struct stat st;
    if (lstat(target.c_str(), &st) != 0) {
        if (std::rename(from.c_str(), target.c_str()) != 0)
            fail("cannot rename ", from, " to ", target, ": ", std::strerror(errno));
    }
    else if (exchange(from, target)) {
        remove_tree(from); // now holds the previous version
    }
    else {
        // fallback: a short window in which only the .old copy exists
        const std::string old = sibling(target, "old");
        remove_tree(old);
        if (std::rename(target.c_str(), old.c_str()) != 0)
            fail("cannot rename ", target, " to ", old, ": ", std::strerror(errno));
        if (std::rename(from.c_str(), target.c_str()) != 0) {
            const int error = errno;
            std::rename(old.c_str(), target.c_str());
            fail("cannot rename ", from, " to ", target, ": ", std::strerror(error));
        }
        remove_tree(old);
    }
    sync_path(parent_of(target));
}

void remove_directory(const std::string &path)
{
    // out of its name first: a removal cut short leaves only a hidden rest
    const std::string doomed = sibling(path, "removed");
    remove_tree(doomed);
    if (std::rename(path.c_str(), doomed.c_str()) != 0)
        fail("cannot rename ", path, " to ", doomed, ": ", std::strerror(errno));
    sync_path(parent_of(path));
    if (!remove_tree(doomed))
        fail("removed from the list, but cannot delete ", doomed);
}

} // namespace sbrt
