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

#include <chrono>
#include <filesystem>

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
    const std::string path = temp_ + "/" + name;
    FILE *fp = std::fopen(path.c_str(), "wb");
    if (!fp)
        fail("AtomicDirectory: cannot create ", path, ": ",
             std::strerror(errno));
    const size_t written =
        bytes.empty() ? 0 : std::fwrite(bytes.data(), 1, bytes.size(), fp);
    const bool flushed = std::fflush(fp) == 0 && fsync(fileno(fp)) == 0;
    const bool closed = std::fclose(fp) == 0;
    if (written != bytes.size() || !flushed || !closed)
        fail("AtomicDirectory: cannot write ", path, " (", bytes.size(),
             " bytes): ", std::strerror(errno));
}

void AtomicDirectory::write_file(const std::string &name,
                                 const std::string &text)
{
    write_file(name, std::vector<uint8_t>(text.begin(), text.end()));
}

void AtomicDirectory::commit()
{
    sync_path(temp_);
    struct stat st;
    if (stat(target_.c_str(), &st) != 0) {
        if (std::rename(temp_.c_str(), target_.c_str()) != 0)
            fail("AtomicDirectory: cannot rename ", temp_, " to ", target_,
                 ": ", std::strerror(errno));
    }
    else if (exchange(temp_, target_)) {
        remove_tree(temp_); // now holds the previous version
    }
    else {
        // fallback: a short window in which only the .old copy exists
        const std::string old = sibling(target_, "old");
        remove_tree(old);
        if (std::rename(target_.c_str(), old.c_str()) != 0 ||
            std::rename(temp_.c_str(), target_.c_str()) != 0)
            fail("AtomicDirectory: cannot replace ", target_, ": ",
                 std::strerror(errno));
        remove_tree(old);
    }
    sync_path(parent_of(target_));
    committed_ = true;
}

} // namespace sbrt
