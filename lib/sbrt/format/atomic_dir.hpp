/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Writes a directory of files so that it appears all at once:
 *            a killed run leaves the previous directory intact
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_ATOMIC_DIR_HPP
#define SBRT_ATOMIC_DIR_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace sbrt {

class FileDescriptor;

/// \brief A temporary sibling directory that replaces `target` on commit().
/// Destroyed without commit(), it removes itself and `target` is untouched.
/// What a killed writer of `target` left (its hidden temporary, once its
/// process no longer runs and nothing in it changed for an hour) is
/// removed by the next writer of `target`.
class AtomicDirectory {
public:
    explicit AtomicDirectory(std::string target);
    ~AtomicDirectory();
    AtomicDirectory(const AtomicDirectory &) = delete;
    AtomicDirectory &operator=(const AtomicDirectory &) = delete;

    /// Writes one file into the temporary directory and syncs it. `name`
    /// is one entry of the directory: no '/', not "." or "..".
    void write_file(const std::string &name, const std::vector<uint8_t> &bytes);
    void write_file(const std::string &name, const std::string &text);
    /// Copies the whole regular file open as `source` (`what` names it in
    /// errors) into the temporary directory as `name` and syncs it: a
    /// staged copy of another directory, file by file.
    void copy_file(const std::string &name, const FileDescriptor &source,
                   const std::string &what);
    /// Where a file streamed by its writer goes (synced by that writer).
    std::string file_path(const std::string &name) const { return temp_ + "/" + name; }
    /// Swaps the temporary directory into place (renameat2 RENAME_EXCHANGE
    /// where the file system has it, else two renames) and drops the old one.
    void commit();

private:
    std::string target_;
    std::string temp_;
    bool committed_ = false;
};

class MemberDirectory;

/// \brief Stages in `out` every member of SBRT `dir` but those named in
/// `replaced` and "hist": hard links where the file system allows (nothing
/// ever writes into a member in place), copies else. Returns the text of
/// the history member, to which a rewrite adds its line. Throws
/// sbrt::Error where a member is no regular file.
std::string stage_other_members(const MemberDirectory &dir, AtomicDirectory &out,
                                const std::vector<std::string> &replaced);

/// Removes a directory tree; returns false if something could not be removed.
bool remove_tree(const std::string &path);

/// \brief Moves directory `from` to `target`, whose previous content goes
/// (what commit() does with the temporary): one renameat2 RENAME_EXCHANGE
/// where the file system has it, so that `target` is never missing; else
/// `target` is renamed aside to its hidden sibling `.name.old.PID` first,
/// and given its name back if the second rename fails. Throws sbrt::Error;
/// on failure `from` and `target` are as they were.
void replace_directory(const std::string &from, const std::string &target);

/// \brief Removes directory `path`: it leaves its name in one rename (to
/// its hidden sibling `.name.removed.PID`) before its files are deleted,
/// so a removal cut short leaves only a hidden rest. Throws sbrt::Error.
void remove_directory(const std::string &path);

} // namespace sbrt

#endif
