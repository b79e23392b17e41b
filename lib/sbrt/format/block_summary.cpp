/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Block summaries: built while a block is written, stored as
 *            a checksummed section, read and checked without a block
 *            decoded, and the model's Table 1 figures made from them
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/block_summary.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "format/stacks_fields.hpp"
#include "format/stacks_v2_layout.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

constexpr size_t RECORD_BYTES = 28; ///< a record without its materials
constexpr size_t TRAILER_BYTES = 16;
constexpr uint16_t FLAG_COMPACT = 1;

} // namespace

bool BlockSummary::holds(uint32_t material) const
{
    return material <= UINT16_MAX &&
           std::binary_search(materials.begin(), materials.end(), uint16_t(material));
}

bool BlockSummary::operator==(const BlockSummary &o) const
{
    // the empty marker's infinities compare equal as floats
    return intervals == o.intervals && solid_intervals == o.solid_intervals &&
           longest_stack == o.longest_stack && filled_cells == o.filled_cells &&
           z_low == o.z_low && z_high == o.z_high && compact == o.compact &&
           materials == o.materials;
}

BlockSummarizer::BlockSummarizer(size_t material_count)
    : present_((material_count + 63) / 64, 0)
{
}

void BlockSummarizer::add_stack(const Model &model, uint64_t cell)
{
    const StackRange stack = model.stack(cell);
    if (stack.size() == 0)
        return;
    s_.intervals += uint32_t(stack.size());
    s_.longest_stack = std::max(s_.longest_stack, uint32_t(stack.size()));
    ++s_.filled_cells;
    model.intervals().visit([&](const auto *records) {
        const auto &first = records[stack.begin];
        // the stack's material begins above a leading EMPTY interval
        const float low = first.material == EMPTY ? float(first.top) : 0.0f;
        s_.z_low = std::min(s_.z_low, low);
        s_.z_high = std::max(s_.z_high, float(records[stack.end - 1].top));
        for (uint64_t i = stack.begin; i < stack.end; ++i) {
            const uint32_t m = records[i].material;
            if (m != EMPTY) {
                ++s_.solid_intervals;
                present_[m / 64] |= uint64_t(1) << (m % 64);
            }
            if constexpr (!std::is_same_v<RecordOf<decltype(records)>, CompactInterval>)
                s_.compact = s_.compact && fits_compact(records[i]);
        }
    });
}

BlockSummary BlockSummarizer::finish() const
{
    BlockSummary out = s_;
    for (size_t w = 0; w < present_.size(); ++w)
        for (uint64_t bits = present_[w]; bits; bits &= bits - 1)
            out.materials.push_back(uint16_t(w * 64 + unsigned(__builtin_ctzll(bits))));
    return out;
}

std::vector<uint8_t> encode_block_summaries(const std::vector<BlockSummary> &blocks)
{
    ByteWriter out;
    for (const BlockSummary &b : blocks) {
        out.u32(b.intervals);
        out.u32(b.solid_intervals);
        out.u32(b.longest_stack);
        out.u32(b.filled_cells);
        out.f32(b.z_low);
        out.f32(b.z_high);
        out.u16(b.compact ? FLAG_COMPACT : 0);
        out.u16(uint16_t(b.materials.size()));
        for (const uint16_t m : b.materials)
            out.u16(m);
    }
    const uint32_t crc = crc32_of(out.bytes().data(), out.size());
    out.u32(uint32_t(blocks.size()));
    out.u32(crc);
    out.u64(out.size() + 8);
    return std::move(out.bytes());
}

namespace {

/// One record's fields against the block's limits; what is wrong, or "".
std::string record_problem(const BlockSummary &s, uint64_t cells, uint32_t intervals,
                           const SummaryBounds &b)
{
    if (s.intervals != intervals)
        return "holds another interval count than the block table";
    if (s.solid_intervals > s.intervals || s.longest_stack > s.intervals ||
        s.filled_cells > cells || s.filled_cells > s.intervals ||
        (s.filled_cells == 0) != (s.intervals == 0) ||
        s.solid_intervals < s.filled_cells ||
        uint64_t(s.longest_stack) * s.filled_cells < s.intervals)
        return "has counts no block can have";
    if (b.count_bytes < 4 && s.longest_stack >> (8 * b.count_bytes))
        return "has a stack longer than the file's counts hold";
    if (s.is_empty()) {
        if (!(std::isinf(s.z_low) && s.z_low > 0 && std::isinf(s.z_high) && s.z_high < 0))
            return "is empty but has a height range";
    }
    else if (!(s.z_low >= 0 && s.z_low < s.z_high && s.z_high <= float(b.depths)))
        return "has a height range outside the model";
    if (b.all_compact && !s.compact)
        return "has wide intervals in a model of voxel tops";
    if (s.materials.size() > s.solid_intervals ||
        s.materials.empty() != (s.solid_intervals == 0))
        return "lists another number of classes than its intervals hold";
    for (size_t i = 0; i < s.materials.size(); ++i)
        if (s.materials[i] == EMPTY || s.materials[i] >= b.materials ||
            (i > 0 && s.materials[i] <= s.materials[i - 1]))
            return "lists classes out of range or order";
    return "";
}

} // namespace

uint64_t find_block_summaries(const uint8_t *data, uint64_t blocks_end, uint64_t end,
                              size_t blocks, const std::string &what)
{
    const std::string where = what + " block summaries";
    // the trailer: count, checksum, the section's size
    if (end < blocks_end || end - blocks_end < TRAILER_BYTES)
        fail(where, ": missing (corrupt file)");
    ByteReader trailer(data + end - TRAILER_BYTES, TRAILER_BYTES, where);
    const uint32_t count = trailer.u32(), crc = trailer.u32();
    const uint64_t bytes = trailer.u64();
    if (count != blocks || bytes < TRAILER_BYTES + blocks * RECORD_BYTES ||
        bytes > end - blocks_end)
        fail(where, ": size does not match the ", blocks, " blocks (corrupt file)");
    if (crc32_of(data + end - bytes, size_t(bytes) - TRAILER_BYTES) != crc)
        fail(where, ": checksum mismatch (corrupt file)");
    return end - bytes;
}

std::vector<BlockSummary> decode_block_summaries(const uint8_t *data, uint64_t begin,
                                                 uint64_t end, const SummaryBounds &bounds,
                                                 const std::string &what)
{
    const std::string where = what + " block summaries";
    const size_t blocks = bounds.cells.size();
    const uint8_t *records = data + begin;
    const size_t records_bytes = size_t(end - begin) - TRAILER_BYTES;

    // the records, each checked against its block
    ByteReader in(records, records_bytes, where);
    std::vector<BlockSummary> out(blocks);
    for (size_t k = 0; k < blocks; ++k) {
        BlockSummary &s = out[k];
        s.intervals = in.u32();
        s.solid_intervals = in.u32();
        s.longest_stack = in.u32();
        s.filled_cells = in.u32();
        s.z_low = in.f32();
        s.z_high = in.f32();
        const uint16_t flags = in.u16();
        if (flags & ~FLAG_COMPACT)
            fail(where, ": block ", k, " has unknown flags (corrupt file)");
        s.compact = (flags & FLAG_COMPACT) != 0;
        s.materials.resize(in.u16());
        for (uint16_t &m : s.materials)
            m = in.u16();
        const std::string problem = record_problem(s, bounds.cells[k], bounds.intervals[k], bounds);
        if (!problem.empty())
            fail(where, ": block ", k, " ", problem, " (corrupt file)");
    }
    if (in.position() != records_bytes)
        fail(where, ": ", records_bytes - in.position(), " bytes after the last block "
             "(corrupt file)");
    return out;
}

Stats summary_stats(const Frame &frame, size_t material_count,
                    const std::vector<BlockSummary> &blocks)
{
    // as Model::stats() of the model decode_stacks_v2 makes: intervals of
    // 4 bytes where every one is compact, else 8
    uint64_t intervals = 0, solid = 0;
    uint32_t longest = 0;
    bool compact = true;
    for (const BlockSummary &b : blocks) {
        intervals += b.intervals;
        solid += b.solid_intervals;
        longest = std::max(longest, b.longest_stack);
        compact = compact && b.compact;
    }
    return stats_of(frame, intervals, solid, longest,
                    StackIndex::bytes_for(frame.cells(), longest), compact ? 4 : 8,
                    material_count);
}

uint64_t ModelSummary::largest_decoded_block() const
{
    const BlockGrid grid{frame.rows, frame.cols, block_size};
    uint64_t most = 0;
    for (size_t b = 0; b < blocks.size(); ++b) {
        const BlockSummary &s = blocks[b];
        most = std::max(most, StackIndex::bytes_for(grid.cells(int(b)), s.longest_stack) +
                                  uint64_t(s.intervals) * (s.compact ? 4 : 8));
    }
    return most;
}

double ModelSummary::highest_top_local() const
{
    double top = 0;
    for (const BlockSummary &block : blocks)
        if (!block.is_empty())
            top = std::max(top, double(block.z_high));
    return top;
}

std::optional<ModelSummary> read_stacks_summary(const uint8_t *data, size_t size,
                                                const std::string &what)
{
    if (stacks_major_version(data, size) != FORMAT_V2_MAJOR)
        return std::nullopt; // v1 (or no stacks file: the decode says which)
    const StacksV2Layout layout = open_stacks_v2(data, size, what);
    const HeaderV2 &h = layout.header;
    if (!(h.optional & V2_OPTIONAL_SUMMARY))
        return std::nullopt;

    SummaryBounds bounds;
    for (size_t b = 0; b < layout.entries.size(); ++b) {
        bounds.cells.push_back(layout.grid.cells(int(b)));
        bounds.intervals.push_back(layout.entries[b].intervals);
    }
    bounds.materials = h.materials;
    bounds.depths = h.frame.depths;
    bounds.count_bytes = h.widths.count_bytes;
    bounds.all_compact = h.widths.tops == TopEncoding::VoxelBoundaries &&
                         voxel_tops_fit_compact(h.frame.depths);
    ModelSummary out;
    out.blocks = decode_block_summaries(data, layout.summary_at, h.table_at, bounds, what);
    out.frame = h.frame;
    out.materials = layout.materials;
    out.block_size = int(h.block_size);
    out.tops = h.widths.tops;
    out.stats = summary_stats(out.frame, out.materials.size(), out.blocks);
    return out;
}

} // namespace sbrt
