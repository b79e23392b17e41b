/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Per-block summaries of a format 2.1 `stacks` file (intervals,
 *            longest stack, cells holding material, height range, the
 *            classes present): what describing a model, and a tracer
 *            before its first ray, needs without decoding any block
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BLOCK_SUMMARY_HPP
#define SBRT_BLOCK_SUMMARY_HPP

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "format/byte_io.hpp"
#include "format/format_v2.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief What one block of cells holds, summed over its stacks.
struct BlockSummary {
    uint32_t intervals = 0;
    uint32_t solid_intervals = 0; ///< of them not EMPTY
    uint32_t longest_stack = 0;
    /// Cells whose stack holds an interval: no stack ends EMPTY, so each
    /// of them holds material.
    uint32_t filled_cells = 0;
    /// Local heights (0 .. depths): from the top of each stack's leading
    /// EMPTY interval (0 where it starts solid) to the highest top. An
    /// empty block has low +inf, high -inf.
    float z_low = std::numeric_limits<float>::infinity();
    float z_high = -std::numeric_limits<float>::infinity();
    /// Every interval is exact as a CompactInterval (4 bytes in memory).
    bool compact = true;
    /// The material indices (not EMPTY) of its intervals, ascending. A
    /// list, not a bitset of the material count: its size is bounded by
    /// the block's solid intervals, where a bitset of 65536 materials
    /// would take 8 KiB a block however few it holds.
    std::vector<uint16_t> materials;

    bool is_empty() const { return filled_cells == 0; }
    /// Whether an interval of `material` lies in the block.
    bool holds(uint32_t material) const;
    bool operator==(const BlockSummary &other) const;
};

/// \brief Builds one block's summary stack by stack.
class BlockSummarizer {
public:
    /// For a model of `material_count` materials (EMPTY included).
    explicit BlockSummarizer(size_t material_count);
    /// Adds the stack of `cell` of `model`.
    void add_stack(const Model &model, uint64_t cell);
    /// The summary of the stacks added.
    BlockSummary finish() const;

private:
    BlockSummary s_;
    std::vector<uint64_t> present_; ///< a bit per material
};

/// The summary section of blocks `blocks` (row by row of blocks): the
/// records, then u32 block count, u32 crc32 of the records, u64 bytes of
/// the section (these 16 included), so that a reader finds the section
/// from its end. A record: u32 intervals, solid intervals, longest stack,
/// cells holding material; f32 z low, z high; u16 flags (bit 0: every
/// interval compact); u16 material count n; n u16 material indices.
std::vector<uint8_t> encode_block_summaries(const std::vector<BlockSummary> &blocks);

/// \brief The limits a summary section must keep: the file's grid, its
/// block table's interval counts and its header's fields.
struct SummaryBounds {
    std::vector<uint64_t> cells;     ///< of each block
    std::vector<uint32_t> intervals; ///< of each block, from the block table
    uint32_t materials = 1;          ///< EMPTY included
    int depths = 1;
    unsigned count_bytes = 4;        ///< the file's stack count width
    bool all_compact = false;        ///< every interval must be compact
};

/// Where the summary section of `blocks` blocks that ends at `end` (the
/// block table's offset) begins: at or after `blocks_end` (the end of the
/// last block), its size and checksum checked; throws sbrt::Error naming
/// `what` otherwise.
uint64_t find_block_summaries(const uint8_t *data, uint64_t blocks_end, uint64_t end,
                              size_t blocks, const std::string &what);

/// Reads the section [begin, end) that find_block_summaries found and
/// checks every record against `bounds`; throws sbrt::Error naming `what`
/// where one does not hold.
std::vector<BlockSummary> decode_block_summaries(const uint8_t *data, uint64_t begin,
                                                 uint64_t end, const SummaryBounds &bounds,
                                                 const std::string &what);

/// \brief A model described from its header, materials and block
/// summaries: no block decoded.
struct ModelSummary {
    Frame frame;
    std::vector<Material> materials; ///< EMPTY first
    std::string vertical_datum;      ///< where the SBRT names one (read_sbrt_summary)
    bool has_channels = false;       ///< the SBRT has property channels (read_sbrt_summary)
    int block_size = 0;
    /// How the file stores tops: VoxelBoundaries where every top lies on a
    /// voxel boundary (the writer's widths_for(model).tops)
    TopEncoding tops = TopEncoding::Float32;
    std::vector<BlockSummary> blocks; ///< row by row of blocks
    Stats stats;                      ///< as Model::stats() of the decoded model

    /// The highest top (local height, 0 .. depths) of any stack: as
    /// highest_top_local() of the decoded model, 0 where it is empty.
    double highest_top_local() const;
    /// The bytes the largest block takes decoded (StackBlock::bytes): the
    /// least a paged model's budget may be.
    uint64_t largest_decoded_block() const;
};

/// The figures Model::stats() gives for the decoded model of `frame`,
/// `material_count` materials and these blocks.
Stats summary_stats(const Frame &frame, size_t material_count,
                    const std::vector<BlockSummary> &blocks);

/// The summary of untrusted `stacks` bytes: header, materials and block
/// summaries read and checked (sizes, offsets, checksums), no block
/// decoded; nothing where the file has no summaries (a v1 or 2.0 file:
/// decode it instead). A damaged file throws sbrt::Error naming `what`.
std::optional<ModelSummary> read_stacks_summary(const uint8_t *data, size_t size,
                                                const std::string &what);

} // namespace sbrt

#endif
