/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   Copy, rename, removal and listing of whole SBRT directories
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_manage.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <set>

#include "util/error.hpp"
#include "grass.hpp"
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

/// Hidden sibling of `target` for work in progress, named as lib/sbrt's
/// AtomicDirectory names its own: list_stored_sbrts, list_sbrts and g.list
/// skip it, and a leftover of a killed run is recognisable.
fs::path hidden_sibling(const fs::path &target, const char *tag)
{
    return target.parent_path() / ("." + target.filename().string() + "." +
                                   tag + "." + std::to_string(getpid()));
}

void sync_path(const fs::path &path)
{
    const int fd = open(path.c_str(), O_RDONLY);
    if (fd >= 0) {
        fsync(fd);
        close(fd);
    }
}

void rename_or_fail(const fs::path &from, const fs::path &to, const char *where)
{
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec)
        fail(where, ": cannot rename ", from.string(), " to ", to.string(),
             " (", ec.message(), ")");
}

/// Copies the files (and any subdirectories) of `from` into the new
/// directory `to`, each synced so that the later rename publishes whole
/// files even after a crash.
void copy_tree_synced(const fs::path &from, const fs::path &to)
{
    std::error_code ec;
    fs::create_directory(to, ec);
    if (ec)
        fail("copy_sbrt: cannot create ", to.string(), " (", ec.message(), ")");
    for (fs::recursive_directory_iterator it(from, ec), end; !ec && it != end;
         it.increment(ec)) {
        const fs::path copy = to / fs::relative(it->path(), from);
        if (it->is_directory())
            fs::create_directory(copy, ec);
        else if (fs::copy_file(it->path(), copy, ec))
            sync_path(copy);
        if (ec)
            fail("copy_sbrt: cannot copy ", it->path().string(), " to ",
                 copy.string(), " (", ec.message(), ")");
    }
    if (ec)
        fail("copy_sbrt: cannot read ", from.string(), " (", ec.message(), ")");
}

/// Appends to `hist` who copied the SBRT from where, in write_sbrt_map's
/// "key: value" lines, so the history tells a copy from its original.
void append_copy_history(const fs::path &directory, const StoredSbrt &source)
{
    const time_t now = time(nullptr);
    char date[64];
    strftime(date, sizeof date, "%a %b %d %H:%M:%S %Y", localtime(&now));
    const fs::path hist = directory / "hist";
    std::ofstream out(hist, std::ios::app);
    out << "copied: " << date << "\n"
        << "copied from: " << source.qualified() << "\n"
        << "copied by: " << G_whoami() << "\n"
        << "copy command: " << G_recreate_command() << "\n";
    out.close();
    if (!out)
        fail("copy_sbrt: cannot write ", hist.string());
    sync_path(hist);
}

/// Moves `from` to `target`, whose previous content goes away first: one
/// rename when `target` is free, else `target` is moved aside, `from` takes
/// its name and the old content is deleted. If the second rename fails the
/// old content gets its name back.
void replace_directory(const fs::path &from, const fs::path &target,
                       const char *where)
{
    std::error_code ec;
    if (!fs::exists(target, ec)) {
        rename_or_fail(from, target, where);
        return;
    }
    const fs::path aside = hidden_sibling(target, "old");
    rename_or_fail(target, aside, where);
    fs::rename(from, target, ec);
    if (ec) {
        fs::rename(aside, target, ec);
        fail(where, ": cannot rename ", from.string(), " to ", target.string(),
             " (", ec.message(), ")");
    }
    fs::remove_all(aside, ec);
}

/// Publishes the finished copy `staged` as `target`: where the file system
/// can swap two names in one step (renameat2 RENAME_EXCHANGE, Linux 3.15),
/// `target` is never missing; elsewhere replace_directory's two renames.
void publish_directory(const fs::path &staged, const fs::path &target)
{
    std::error_code ec;
    if (fs::exists(target, ec) &&
        renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, target.c_str(),
                  RENAME_EXCHANGE) == 0) {
        fs::remove_all(staged, ec); // now holds the replaced SBRT
    }
    else {
        replace_directory(staged, target, "copy_sbrt");
    }
    sync_path(target.parent_path());
}

/// The temporary directory of a copy: removed again unless published.
class StagedCopy {
public:
    explicit StagedCopy(const fs::path &target)
        : target_(target), path_(hidden_sibling(target, "tmp"))
    {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ~StagedCopy()
    {
        std::error_code ec;
        if (!published_)
            fs::remove_all(path_, ec);
    }
    StagedCopy(const StagedCopy &) = delete;
    StagedCopy &operator=(const StagedCopy &) = delete;

    const fs::path &path() const { return path_; }
    void publish()
    {
        sync_path(path_);
        publish_directory(path_, target_);
        published_ = true;
    }

private:
    fs::path target_;
    fs::path path_;
    bool published_ = false;
};

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
    require_legal_name(target, "copy_sbrt");
    G_make_mapset_object_group(ELEMENT);
    StagedCopy staged(sbrt_directory(target, G_mapset()));
    copy_tree_synced(sbrt_directory(source.name, source.mapset), staged.path());
    append_copy_history(staged.path(), source);
    staged.publish();
}

void rename_sbrt(const std::string &from, const std::string &to)
{
    require_legal_name(from, "rename_sbrt");
    require_legal_name(to, "rename_sbrt");
    const fs::path old_path = sbrt_directory(from, G_mapset());
    std::error_code ec;
    if (!fs::is_directory(old_path, ec))
        fail("rename_sbrt: no SBRT at ", old_path.string());
    replace_directory(old_path, sbrt_directory(to, G_mapset()), "rename_sbrt");
    sync_path(old_path.parent_path());
}

void remove_sbrt(const std::string &name)
{
    require_legal_name(name, "remove_sbrt");
    const fs::path path = sbrt_directory(name, G_mapset());
    std::error_code ec;
    if (!fs::is_directory(path, ec))
        fail("remove_sbrt: no SBRT at ", path.string());
    // out of its name first: a removal cut short leaves only a hidden rest
    const fs::path doomed = hidden_sibling(path, "removed");
    rename_or_fail(path, doomed, "remove_sbrt");
    fs::remove_all(doomed, ec);
    if (ec)
        fail("remove_sbrt: removed from the list, but cannot delete ",
             doomed.string(), " (", ec.message(), ")");
}

} // namespace sbrt_grass
