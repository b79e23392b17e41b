/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Copy, rename, removal and listing of whole SBRT directories
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_manage.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <set>

#include "format/atomic_dir.hpp"
#include "format/member_dir.hpp"
#include "util/error.hpp"
#include "grass.hpp"
#include "map_names.hpp"
#include "raster_metadata.hpp"
#include "sbrt_store.hpp"

namespace sbrt_grass {

namespace fs = std::filesystem;
using sbrt::fail;

namespace {

/// G_legal_filename without its warnings: callers check names with their
/// own messages first; this guards every path built here, so that no name
/// leaves the sbrt element (no '/', no leading '.').
bool is_legal_name(const std::string &name)
{
    const int previous = G_suppress_warnings(1);
    const bool legal = G_legal_filename(name.c_str()) == 1;
    G_suppress_warnings(previous);
    return legal;
}

void require_legal_name(const std::string &name, const char *where)
{
    if (!is_legal_name(name))
        fail(where, ": illegal SBRT name (", name, ")");
}

/// `hist` of the copy: the source's (if it has one) and a record of who
/// copied it from where, in write_sbrt_map's "key: value" lines, so the
/// history tells a copy from its original.
std::string history_of_copy(const sbrt::MemberDirectory &from,
                            const StoredSbrt &source)
{
    std::string history;
    if (const auto hist = from.open_regular_if_present("hist")) {
        const std::vector<uint8_t> bytes =
            sbrt::read_all(*hist, from.member_path("hist"));
        history.assign(bytes.begin(), bytes.end());
    }
    history += "copied: " + history_date() + "\n";
    history += "copied from: " + source.qualified() + "\n";
    history += std::string("copied by: ") + G_whoami() + "\n";
    history += std::string("copy command: ") + G_recreate_command() + "\n";
    return history;
}

/// Whether there is an entry `path` (a link counts as itself: renamed or
/// removed, never followed).
bool has_entry(const std::string &path)
{
    struct stat st;
    return lstat(path.c_str(), &st) == 0;
}

} // namespace

std::string sbrt_directory(const std::string &name, const std::string &mapset)
{
    char path[GPATH_MAX];
    G_file_name(path, ELEMENT, name.c_str(), mapset.c_str());
    return path;
}

std::optional<StoredSbrt> find_stored_sbrt(const std::string &name,
                                           const std::string &mapset)
{
    // G_name_is_fully_qualified copies both parts without a bound
    if (name.size() >= size_t(std::min(GNAME_MAX, GMAPSET_MAX)))
        return std::nullopt;
    char bare[GNAME_MAX], qualifier[GMAPSET_MAX];
    const bool qualified =
        G_name_is_fully_qualified(name.c_str(), bare, qualifier);
    const std::string base = qualified ? bare : name;
    if (!is_legal_name(base))
        return std::nullopt;
    // a mapset named by the user must be one of the location (issue 28)
    if ((qualified && !is_location_mapset(qualifier)) ||
        (!mapset.empty() && !is_location_mapset(mapset.c_str())))
        return std::nullopt;
    const char *found = G_find_file2(ELEMENT, name.c_str(), mapset.c_str());
    if (!found)
        return std::nullopt;
    return StoredSbrt{base, found};
}

std::vector<StoredSbrt>
list_stored_sbrts(const std::vector<std::string> &mapsets)
{
    std::vector<StoredSbrt> found;
    const std::set<std::string> unique(mapsets.begin(), mapsets.end());
    for (const std::string &mapset : unique) {
        std::error_code ec;
        for (fs::directory_iterator it(sbrt_directory("", mapset), ec), end;
             !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (name[0] != '.' && it->is_directory())
                found.push_back({name, mapset});
        }
    }
    std::sort(found.begin(), found.end(),
              [](const StoredSbrt &a, const StoredSbrt &b) {
                  return a.name != b.name ? a.name < b.name
                                          : a.mapset < b.mapset;
              });
    return found;
}

void copy_sbrt(const StoredSbrt &source, const std::string &target)
{
    require_legal_name(source.name, "copy_sbrt");
    check_new_name(target.c_str(), true, "copy");
    // the source may be another user's: read as untrusted (issue 28), its
    // members relative to it, regular files only, never through a link
    const sbrt::MemberDirectory from(sbrt_directory(source.name, source.mapset));
    G_make_mapset_object_group(ELEMENT);
    const sbrt::SbrtLock lock = lock_for_writing(sbrt_directory(target, G_mapset()));
    sbrt::AtomicDirectory staged(sbrt_directory(target, G_mapset()));
    for (const std::string &name : from.member_names()) {
        if (name == "hist")
            continue;
        sbrt::FileDescriptor member;
        try {
            member = from.open_regular(name);
        }
        catch (const sbrt::Error &e) {
            fail(e.what(), "; nothing copied: the owner of mapset <",
                 source.mapset, "> can convert the model again");
        }
        staged.copy_file(name, member, from.member_path(name));
    }
    staged.write_file("hist", history_of_copy(from, source));
    staged.commit();
}

void rename_sbrt(const std::string &from, const std::string &to)
{
    require_legal_name(from, "rename_sbrt");
    check_new_name(to.c_str(), true, "rename");
    const std::string old_path = sbrt_directory(from, G_mapset());
    const std::string new_path = sbrt_directory(to, G_mapset());
    // both writers' locks, in one order (by path) so that two renames
    // the other way round cannot wait for each other
    const auto [first, second] = std::minmax(old_path, new_path);
    const sbrt::SbrtLock first_lock = lock_for_writing(first);
    const std::optional<sbrt::SbrtLock> second_lock =
        second != first ? std::optional<sbrt::SbrtLock>(lock_for_writing(second)) : std::nullopt;
    if (!has_entry(old_path))
        fail("rename_sbrt: no SBRT at ", old_path);
    sbrt::replace_directory(old_path, new_path);
}

void remove_sbrt(const std::string &name)
{
    require_legal_name(name, "remove_sbrt");
    const std::string path = sbrt_directory(name, G_mapset());
    const sbrt::SbrtLock lock = lock_for_writing(path);
    if (!has_entry(path))
        fail("remove_sbrt: no SBRT at ", path);
    sbrt::remove_directory(path);
}

} // namespace sbrt_grass
