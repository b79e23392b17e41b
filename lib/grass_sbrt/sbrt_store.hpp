/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   SBRTs as the mapset element sbrt/<name>: look-up across the
 *            search path, output paths, listing, overwrite checks, history
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STORE_HPP
#define SBRT_STORE_HPP

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "format/format.hpp"
#include "format/sbrt_lock.hpp"
#include "model/model.hpp"

namespace sbrt_grass {

constexpr const char *ELEMENT = "sbrt";

/// Whether `mapset` is the name of a mapset of the current location (a
/// legal name that G_get_available_mapsets lists): what a user's mapset
/// name must be before it becomes part of a path.
bool is_location_mapset(const char *mapset);
/// Directory of an existing SBRT `name` or `name@mapset` (a mapset of the
/// location); throws sbrt::Error with advice when it is not found. Errors
/// are exceptions, not fatal errors, so that the view server answers them
/// and goes on; the modules turn them into G_fatal_error.
std::string find_sbrt(const char *name);
/// Reads an SBRT (all of it, or what `options` ask for); a damaged one,
/// or one with a member that is no regular file, throws sbrt::Error
/// naming the map and what to do.
sbrt::Model read_sbrt_map(const char *name, const sbrt::ReadOptions &options = {});
/// SBRT `name` as a paged model (sbrt::read_sbrt_paged): its blocks
/// decoded as they are read, within paging.budget_bytes; nothing where its
/// stacks are older than format 2.1.
std::optional<sbrt::Model> read_sbrt_paged_map(const char *name, const sbrt::Paging &paging);
/// The coarse level of detail of SBRT `name` (member stacks_lod: a level
/// for frames drawn while the camera moves, never for exact output) with
/// the frame of its exact model; nothing where the SBRT has none (written
/// before r3.sbrt stored one, or under 512 x 512 cells). A damaged member
/// throws sbrt::Error naming it and what to do.
std::optional<sbrt::CoarseLevel> read_sbrt_lod_map(const char *name);
/// Describes SBRT `name` from its header, materials and block summaries
/// (sbrt::read_sbrt_summary): milliseconds, no block decoded. Nothing
/// where its stacks have no summaries (written before format 2.1: read
/// the model instead); a damaged summary throws sbrt::Error naming the
/// map and what to do.
std::optional<sbrt::ModelSummary> read_sbrt_summary_map(const char *name);
/// The property channels of SBRT `name` whose model (as read) is `model`;
/// nullptr where it has none. A damaged channels member throws
/// sbrt::Error naming the map and what to do.
std::shared_ptr<const sbrt::PropertyChannels> read_channels_map(const char *name,
                                                                const sbrt::Model &model);
/// \brief The channels of an SBRT and those a probability= sums.
struct ProbabilityChannels {
    std::shared_ptr<const sbrt::PropertyChannels> channels;
    std::vector<size_t> summed;
};
/// The channels of SBRT `name` (model as read: `model`) that `probability`
/// sums (sbrt::probability_channels); throws sbrt::Error where the SBRT has
/// no channels, saying that `option` needs them, or where `probability`
/// names them wrongly.
ProbabilityChannels read_probability_channels(const char *name, const sbrt::Model &model,
                                              const std::string &probability,
                                              const char *option);
/// The writers' lock of SBRT directory `dir` (sbrt::SbrtLock), waited for
/// up to 30 s: every writer (support, convert's output, manage's copy,
/// rename and remove) takes it, so that writes made at once happen one
/// after the other and none is lost (issue 48, item 3); readers never take
/// it. Throws sbrt::Error when another writer holds it all that time.
sbrt::SbrtLock lock_for_writing(const std::string &dir);
/// Checks the name and overwrite rules, then returns the directory of the
/// new SBRT in the current mapset.
std::string new_sbrt_path(const char *name, bool overwrite);
/// Writes SBRT `name` atomically to `path` (from new_sbrt_path), with
/// history, compressing on `threads` threads (0: all cores); with its
/// coarse level of detail (member stacks_lod) where the model is large
/// enough to have one (sbrt::level_of_detail_factor).
void write_sbrt_map(const char *name, const std::string &path,
                    const sbrt::Model &model, const std::string &source,
                    const std::string &channels_file = {}, unsigned threads = 0);
/// "name@mapset" of every SBRT in the search path, mapset by mapset.
std::vector<std::string> list_sbrts();
/// Fatal error if a 3D raster `name` exists in the current mapset and
/// overwriting is not allowed.
void check_new_raster3d(const char *name, bool overwrite);

} // namespace sbrt_grass

#endif
