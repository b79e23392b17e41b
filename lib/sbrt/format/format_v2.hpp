/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Format v2 of the `stacks` file: exact and compact. Cells in
 *            square blocks, each block's stacks zstd-compressed on its own
 *            (tops as u16 voxel boundaries where the model has them, else
 *            f32; materials as u8 or u16 indices; counts as u8 or u16 per
 *            cell), 64-bit offsets, a header read by prefix with feature
 *            flags; written as a stream, read block by block on all cores
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FORMAT_V2_HPP
#define SBRT_FORMAT_V2_HPP

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "format/byte_sink.hpp"
#include "model/model.hpp"

namespace sbrt {

/// Version 2.1 (2.0 with the block summaries). A reader takes any 2.x
/// file whose required features it knows; fields a later minor version
/// adds go after those of 2.0.
constexpr uint16_t FORMAT_V2_MAJOR = 2;
constexpr uint16_t FORMAT_V2_MINOR = 1;
/// Size of the 2.0 header (magic to header checksum).
constexpr uint32_t STACKS_V2_HEADER_SIZE = 152;
/// Required feature bits this build understands (none yet: 2.0 files set
/// none). A file with others needs a newer reader; unknown optional bits
/// are ignored.
constexpr uint32_t V2_KNOWN_REQUIRED_FEATURES = 0;
/// Optional feature: the SBRT has a `channels` member (per-voxel property
/// channels, issue 29); readers that do not know it read the classes.
constexpr uint32_t V2_OPTIONAL_CHANNELS = 1u << 0;
/// Optional feature (2.1): a section of per-block summaries lies between
/// the last block and the block table (format/block_summary.hpp); 2.0
/// readers skip it, readers of 2.1 describe the model from it without
/// decoding a block.
constexpr uint32_t V2_OPTIONAL_SUMMARY = 1u << 1;

/// How tops are stored in a block.
enum class TopEncoding : uint8_t {
    VoxelBoundaries = 0, ///< u16, the difference to the top below (exact)
    Float32 = 1,         ///< f32 as in memory (continuous horizons)
};

/// \brief What the writer chooses; block_size cells a side.
struct StacksV2Options {
    int block_size = 64;
    int zstd_level = 3;
    unsigned threads = 0; ///< 0: all cores
    uint32_t optional_features = 0; ///< V2_OPTIONAL_* bits
    /// Writes the block summaries (2.1); false writes a 2.0 file, as
    /// earlier versions did (for tests of older files).
    bool summary = true;
};

/// \brief The field widths a model needs (smallest exact ones).
struct StacksV2Widths {
    uint8_t count_bytes = 1, material_bytes = 1;
    TopEncoding tops = TopEncoding::VoxelBoundaries;
};
StacksV2Widths widths_for(const Model &model);

/// Layout (all little-endian):
///   header: magic "\x89SBRT\r\n\x1a", u16 major 2, u16 minor, u32 header
///   size, u32 required features, u32 optional features, f64 north south
///   east west bottom top, u32 rows cols depths, i32 proj zone, u32
///   material count, u64 interval count, u32 block rows and cols (cells),
///   u8 count bytes, material bytes, top encoding, compression (1: zstd),
///   u64 offsets of materials, block table, end of file, u32 crc32 of
///   materials, of the block table, [later fields], u32 crc32 of the header;
///   materials: i32 class id, u8 red green blue flags (bit 0: has colour);
///   blocks, row by row of blocks: one zstd frame each holding the
///   counts of its cells (row by row), then the materials of its
///   intervals, then their tops;
///   2.1, with V2_OPTIONAL_SUMMARY: the block summaries
///   (encode_block_summaries), ending where the block table begins;
///   block table: u64 offset, u32 compressed size, u32 uncompressed size,
///   u32 intervals, u32 crc32 of the compressed bytes, per block.
void write_stacks_v2(ByteSink &sink, const Model &model,
                     const StacksV2Options &options = {});
std::vector<uint8_t> encode_stacks_v2(const Model &model,
                                      const StacksV2Options &options = {});

/// \brief A rectangle of map coordinates.
struct MapArea {
    double north, south, east, west;
};

/// \brief What a read did.
struct ReadReport {
    uint64_t blocks = 0;      ///< blocks of the file (0: a v1 file)
    uint64_t blocks_read = 0; ///< those decompressed
};

/// \brief How a reader decodes.
struct ReadOptions {
    unsigned threads = 0;      ///< 0: all cores
    uint64_t memory_limit = 0; ///< most bytes the model may take; 0: the RAM
    /// Where given, only the blocks of cells that meet this area (grown by
    /// one cell) are decompressed; the stacks of all other cells are left
    /// empty. v1 files are read whole.
    std::optional<MapArea> area;
    /// Where given, only the stacks of the cells holding these map points
    /// (x, y; cell_of_point) are decoded, from the blocks that hold them
    /// (and meet `area`, where that is given too); every other stack is
    /// left empty. An SBRT with property channels keeps every stack of
    /// those blocks (its channels lie by each column's span). v1 files are
    /// read whole.
    std::optional<std::vector<std::array<double, 2>>> points;
    /// Where given, only the model's rows [first, first + count) are
    /// decoded, as a model of their own: its frame cut to them (full
    /// width), its cells theirs alone; so a module can walk a model band
    /// by band in bounded memory. v1 files are refused with it.
    struct Rows {
        int first = 0, count = 0;
    };
    std::optional<Rows> rows;
    ReadReport *report = nullptr; ///< filled where given
};

/// Bytes a read takes to decode `cells` cells holding `intervals`
/// intervals (pass 1's sizes, 4 bytes a cell, beside the index it builds,
/// `count_bytes` a cell and a group offset; the intervals, `record_bytes`
/// each): what ReadOptions::memory_limit is held against, before anything
/// is allocated.
double decoded_bytes(uint64_t cells, uint64_t intervals, unsigned count_bytes,
                     unsigned record_bytes);

/// The frame of rows [first, first + count) of `frame` (full width); the
/// edges are the frame's own where the rows reach them. Throws
/// sbrt::Error where the rows are not within the frame.
Frame frame_rows(const Frame &frame, int first, int count);

/// Decodes untrusted bytes (checks sizes, offsets, checksums, every
/// block's sizes and every model invariant; throws sbrt::Error naming
/// `what`), blocks decompressed in parallel. A file whose model would
/// take more memory than options.memory_limit is refused before anything
/// is allocated for it.
Model decode_stacks_v2(const uint8_t *data, size_t size, const std::string &what,
                       const ReadOptions &options = {});

} // namespace sbrt

#endif
