/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   On-disk form of an SBRT: a directory with `header` (text,
 *            key: value), `stacks` (binary, checksummed: format v2, v1
 *            still read), `cats`, `colors`, `hist`
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FORMAT_HPP
#define SBRT_FORMAT_HPP

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "format/block_summary.hpp"
#include "format/channels_file.hpp"
#include "format/format_v1.hpp"
#include "format/format_v2.hpp"
#include "format/paged_stacks.hpp"
#include "model/model.hpp"

namespace sbrt {

/// The version write_sbrt writes.
constexpr uint32_t FORMAT_VERSION = 2;

/// Decodes a `stacks` file of any version this build reads (1 or 2.x),
/// told apart by the version after the magic; throws sbrt::Error naming
/// `what` for anything else. `keep` (v1 only) lets the model view mapped
/// bytes instead of copying them.
Model decode_stacks(const uint8_t *data, size_t size, const std::string &what,
                    std::shared_ptr<const void> keep = nullptr,
                    const ReadOptions &options = {});

/// Text `cats`: one "id:label" line per material with a label.
std::string encode_cats(const Model &model);
std::string encode_cats(const std::vector<Material> &materials);
void decode_cats(const std::string &text, Model &model, const std::string &what);
/// The same into a material table (EMPTY first).
void decode_cats(const std::string &text, std::vector<Material> &materials,
                 const std::string &what);

/// Text `colors`: one "id red:green:blue" line per material with a colour
/// of its own. Where an SBRT has this member it is the truth (classes not
/// in it take the default palette); older SBRTs have only the colours in
/// `stacks`.
std::string encode_colors(const Model &model);
std::string encode_colors(const std::vector<Material> &materials);
void decode_colors(const std::string &text, Model &model, const std::string &what);
void decode_colors(const std::string &text, std::vector<Material> &materials,
                   const std::string &what);
/// `datum`: the model's vertical datum, one line ("NAP"); decoding takes
/// at most MAX_DATUM_CHARS printable characters, else throws naming `what`.
constexpr size_t MAX_DATUM_CHARS = 80;
std::string encode_datum(const Model &model);
std::string encode_datum(const std::string &datum);
void decode_datum(const std::string &text, Model &model, const std::string &what);

/// Human-readable `header` (key: value), informational.
std::string encode_header(const Model &model, size_t channels = 0);
std::string encode_header(const Frame &frame, size_t materials, uint64_t intervals,
                          size_t channels = 0);

/// Writes the SBRT directory atomically; `history` goes to `hist`; the
/// stacks in format v2 (SbrtWriter given the model as one band: its
/// blocks compressed, then laid out in the file). Where
/// `channels_file` is given, that finished channels file (written for this
/// model with the stacks' block size) is moved in as member `channels`.
/// Where `coarse` is given (the model's coarse level of detail,
/// scene/level_of_detail.hpp), it is written beside the stacks, with the
/// same writer, as member `stacks_lod`. Member `ranges` holds each
/// column's range of material (format/column_ranges_file.hpp), `tops`
/// each column's top interval (format/column_tops_file.hpp).
void write_sbrt(const std::string &directory, const Model &model,
                const std::string &history, const StacksV2Options &options = {},
                const std::string &channels_file = {}, const Model *coarse = nullptr);
/// The property channels of the SBRT directory whose model (as read) is
/// `model`; nullptr where it has none.
std::shared_ptr<const PropertyChannels> read_channels(const std::string &directory,
                                                      const Model &model);
/// Replaces the `cats` and `colors` of the SBRT directory with those of
/// `model` (read from it, labels and colours changed) and appends
/// `history` to its `hist`, atomically: the other members are hard-linked
/// into the new directory (copied where the file system cannot link), so
/// that a national model's stacks are not rewritten.
void rewrite_legend(const std::string &directory, const Model &model,
                    const std::string &history);
/// Reads and validates an SBRT directory.
Model read_sbrt(const std::string &directory, const ReadOptions &options = {});
/// The SBRT of `directory` as a paged model (format/paged_stacks.hpp):
/// nothing where its stacks are not format 2.1 (read_sbrt it instead).
std::optional<Model> read_sbrt_paged(const std::string &directory, const Paging &paging);
/// \brief The coarse level of detail of an SBRT and the frame of its
/// exact model.
struct CoarseLevel {
    Model model;
    Frame exact;
    /// The exact model's highest top (local units, from its block
    /// summaries), so that a coarse frame is framed and exaggerated as the
    /// exact one; NaN where its stacks have no summaries.
    double exact_top_local = std::numeric_limits<double>::quiet_NaN();
    /// Fine cells a side per coarse cell (rounded).
    int factor() const;
};
/// The model of member `stacks_lod` of an SBRT directory (a coarse level
/// of detail for frames drawn while the camera moves, never for exact
/// output), with the frame of its `stacks`; nothing where the SBRT has no
/// such member (written before it existed, or too small to need one). A
/// damaged member, or one whose extent is not that of `stacks`, throws
/// sbrt::Error naming it.
std::optional<CoarseLevel> read_sbrt_lod(const std::string &directory);
/// Describes an SBRT directory without decoding its model: the header,
/// materials (with `cats` and `colors`), vertical datum and block
/// summaries of a format 2.1 `stacks`, the Table 1 figures read_sbrt's
/// model would give. Nothing where its stacks have no summaries (v1, 2.0:
/// read_sbrt it instead); a damaged member throws sbrt::Error naming it.
std::optional<ModelSummary> read_sbrt_summary(const std::string &directory);
/// \brief What a `stacks` file is on disk.
struct StacksFileInfo {
    uint16_t major = 0, minor = 0;
    uint64_t bytes = 0;
};
/// The version and size of an SBRT directory's `stacks` (throws where it
/// cannot be read or is no stacks file).
StacksFileInfo stacks_file_info(const std::string &directory);
/// Reads the whole file as bytes (throws if missing or unreadable).
std::vector<uint8_t> read_file_bytes(const std::string &path);

} // namespace sbrt

#endif
