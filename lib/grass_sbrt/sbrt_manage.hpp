/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Whole-SBRT store operations (the mapset element sbrt/<name>):
 *            listing per mapset, atomic copy into the current mapset,
 *            rename and removal there. GRASS's rules (overwrite, search
 *            path, messages) stay with the caller; these only touch files.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MANAGE_HPP
#define SBRT_MANAGE_HPP

#include <optional>
#include <string>
#include <vector>

namespace sbrt_grass {

/// \brief One stored SBRT: its name and the mapset that holds it.
struct StoredSbrt {
    std::string name;
    std::string mapset;

    std::string qualified() const { return name + "@" + mapset; }
};

/// The SBRT `name` (or `name@mapset`) in `mapset`, or in the search path
/// when `mapset` is empty; none when it is not there, the name is not a
/// legal one or a mapset named is not one of the location (quietly:
/// callers report names themselves).
std::optional<StoredSbrt> find_stored_sbrt(const std::string &name,
                                           const std::string &mapset);

/// SBRTs of `mapsets` (each listed once), sorted by name, then by mapset,
/// as g.list sorts. Hidden entries (temporary directories) are skipped.
std::vector<StoredSbrt>
list_stored_sbrts(const std::vector<std::string> &mapsets);

/// Directory of SBRT `name` in `mapset`, whether it exists or not.
std::string sbrt_directory(const std::string &name, const std::string &mapset);

/// \brief Copies `source` into the current mapset as `target`, replacing an
/// existing `target`, through sbrt::AtomicDirectory: the files go first to
/// a hidden temporary directory in the current mapset's sbrt element,
/// `hist` gains a record of the copy, and the directory then takes the
/// name: an interrupted copy leaves no partial SBRT under `target`. The
/// source (perhaps another user's) is read as untrusted: its members are
/// regular files opened relative to it, never a symbolic link, FIFO or
/// subdirectory (sbrt::MemberDirectory). Throws sbrt::Error.
void copy_sbrt(const StoredSbrt &source, const std::string &target);

/// \brief Renames SBRT `from` of the current mapset to `to`, replacing an
/// existing `to`. Throws sbrt::Error.
void rename_sbrt(const std::string &from, const std::string &to);

/// \brief Removes SBRT `name` of the current mapset: it leaves its name in
/// one rename before its files are deleted. Throws sbrt::Error.
void remove_sbrt(const std::string &name);

} // namespace sbrt_grass

#endif
