/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   SBRT element in the mapset
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_store.hpp"

#include <sys/stat.h>

#include <cstring>

#include <algorithm>
#include <chrono>
#include <thread>

#include "util/error.hpp"
#include "format/format.hpp"
#include "measure/expected_thickness.hpp"
#include "grass.hpp"
#include "module_errors.hpp"
#include "raster_metadata.hpp"
#include "sbrt_manage.hpp"
#include "sbrt_map_writer.hpp"

namespace sbrt_grass {

namespace {

/// The inode of directory `dir` (0 where it has none).
ino_t inode_of(const std::string &dir)
{
    struct stat st;
    return stat(dir.c_str(), &st) == 0 ? st.st_ino : 0;
}

/// `read(dir)`, read again where a writer replaced the directory while it
/// was read: a rewrite swaps a new directory in and deletes the old one's
/// members, so a reader between the two finds members missing. A reader
/// never waits for a writer; it reads the new SBRT instead.
template <typename Read>
auto read_settled(const std::string &dir, const Read &read)
{
    for (int attempt = 1;; ++attempt) {
        const ino_t before = inode_of(dir);
        try {
            return read(dir);
        }
        catch (const sbrt::Error &) {
            // the same directory, there all along: it is damaged. Else it
            // was swapped (or, where the file system has no rename
            // exchange, is between two renames: no inode): read again
            // after a moment
            const ino_t after = inode_of(dir);
            if (attempt == 5 || (after == before && after != 0))
                throw;
            std::this_thread::sleep_for(std::chrono::milliseconds(10 * attempt));
        }
    }
}

/// read_settled(`read`) of SBRT `name`'s directory; a damaged SBRT fails
/// with `damaged` (translated; "%s" the map's name, then what is wrong),
/// which says what to do.
template <typename Read>
auto read_map(const char *name, const char *damaged, const Read &read)
{
    const std::string dir = find_sbrt(name);
    try {
        return read_settled(dir, read);
    }
    catch (const sbrt::Error &e) {
        fail_with(damaged, name, e.what());
    }
}

} // namespace

bool is_location_mapset(const char *mapset)
{
    const int previous = G_suppress_warnings(1);
    const bool legal = G_legal_filename(mapset) == 1;
    G_suppress_warnings(previous);
    if (!legal)
        return false;
    char **mapsets = G_get_available_mapsets();
    for (int i = 0; mapsets && mapsets[i]; ++i)
        if (std::strcmp(mapsets[i], mapset) == 0)
            return true;
    return false;
}

std::string find_sbrt(const char *name)
{
    char xname[GNAME_MAX], xmapset[GMAPSET_MAX];
    const char *bare = name;
    // G_name_is_fully_qualified copies both parts without a bound
    if (std::strlen(name) < size_t(std::min(GNAME_MAX, GMAPSET_MAX)) &&
        G_name_is_fully_qualified(name, xname, xmapset)) {
        if (!is_location_mapset(xmapset))
            fail_with(_("SBRT <%s>: <%s> is not a mapset of location <%s>; "
                        "name one that g.mapsets -l lists"),
                      name, xmapset, G_location());
        bare = xname;
    }
    const char *mapset = G_find_file2(ELEMENT, name, "");
    if (!mapset)
        fail_with(_("SBRT <%s> not found in the search path; list the "
                    "available ones with r3.sbrt.convert -l"),
                  name);
    char path[GPATH_MAX];
    G_file_name(path, ELEMENT, bare, mapset);
    return path;
}

sbrt::Model read_sbrt_map(const char *name, const sbrt::ReadOptions &options)
{
    return read_map(name,
                    _("SBRT <%s> is damaged or not an SBRT: %s. Convert the source map "
                      "again with r3.sbrt.convert"),
                    [&](const std::string &d) { return sbrt::read_sbrt(d, options); });
}

std::optional<sbrt::Model> read_sbrt_paged_map(const char *name, const sbrt::Paging &paging)
{
    return read_map(name,
                    _("SBRT <%s> is damaged or not an SBRT: %s. Convert the source map "
                      "again with r3.sbrt.convert"),
                    [&](const std::string &d) { return sbrt::read_sbrt_paged(d, paging); });
}

std::optional<sbrt::CoarseLevel> read_sbrt_lod_map(const char *name)
{
    return read_map(name,
                    _("The coarse level of detail of SBRT <%s> is damaged: %s. Render with "
                      "detail=exact, or import the source again with r3.sbrt.convert to "
                      "rewrite it"),
                    [](const std::string &d) { return sbrt::read_sbrt_lod(d); });
}

std::optional<sbrt::ModelSummary> read_sbrt_summary_map(const char *name)
{
    // the blocks may be whole: only an import writes the stacks again
    return read_map(name,
                    _("SBRT <%s> is damaged or not an SBRT: %s. Import its source again "
                      "with r3.sbrt.convert to rewrite it"),
                    [](const std::string &d) { return sbrt::read_sbrt_summary(d); });
}

std::shared_ptr<const sbrt::PropertyChannels> read_channels_map(const char *name,
                                                                const sbrt::Model &model)
{
    return read_map(name,
                    _("The property channels of SBRT <%s> are damaged: %s. Import the source "
                      "file again with r3.sbrt.convert"),
                    [&](const std::string &d) { return sbrt::read_channels(d, model); });
}

ProbabilityChannels read_probability_channels(const char *name, const sbrt::Model &model,
                                              const std::string &probability,
                                              const char *option)
{
    ProbabilityChannels out;
    out.channels = read_channels_map(name, model);
    if (!out.channels)
        fail_with(_("SBRT <%s> has no property channels: %s needs probabilities per voxel "
                    "(import with r3.sbrt.convert properties=)"),
                  name, option);
    out.summed = sbrt::probability_channels(*out.channels, probability);
    return out;
}

std::string new_sbrt_path(const char *name, bool overwrite)
{
    if (G_legal_filename(name) != 1)
        G_fatal_error(_("<%s> is an illegal SBRT name"), name);
    if (G_find_file2(ELEMENT, name, G_mapset()) && !overwrite)
        G_fatal_error(_("option <output>: <%s> exists. To overwrite, use the "
                        "--overwrite flag"),
                      name);
    G_make_mapset_object_group(ELEMENT);
    char path[GPATH_MAX];
    G_file_name(path, ELEMENT, name, G_mapset());
    return path;
}

sbrt::SbrtLock lock_for_writing(const std::string &dir)
{
    return sbrt::SbrtLock(dir, std::chrono::seconds(30));
}

void write_sbrt_map(const char *name, const std::string &path,
                    const sbrt::Model &model, const std::string &source,
                    const std::string &channels_file, unsigned threads)
{
    SbrtMapWriter writer(name, path, model.frame(), threads);
    try {
        model.validate();
        writer.add_rows(model);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Unable to write SBRT <%s>: %s"), name, e.what());
    }
    writer.finish({model.materials(), model.vertical_datum()}, source, channels_file);
}

std::vector<std::string> list_sbrts()
{
    // mapset by mapset in search path order, each sorted by name
    std::vector<std::string> names;
    for (int i = 0; const char *mapset = G_get_mapset_name(i); ++i)
        for (const StoredSbrt &sbrt : list_stored_sbrts({mapset}))
            names.push_back(sbrt.qualified());
    return names;
}

void check_new_raster3d(const char *name, bool overwrite)
{
    if (G_legal_filename(name) != 1)
        G_fatal_error(_("<%s> is an illegal 3D raster map name"), name);
    if (G_find_raster3d(name, G_mapset()) && !overwrite)
        G_fatal_error(_("option <output>: <%s> exists. To overwrite, use the "
                        "--overwrite flag"),
                      name);
}

} // namespace sbrt_grass
