/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Format v2 header written and read by prefix; a file's
 *            sections and block table checked before any block is read
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/stacks_v2_layout.hpp"

#include <cstring>
#include <ios>

#include "format/block_summary.hpp"
#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "util/error.hpp"

namespace sbrt {

uint64_t raw_block_size(const StacksV2Widths &w, uint64_t cells, uint64_t intervals)
{
    const uint64_t top_bytes = w.tops == TopEncoding::VoxelBoundaries ? 2 : 4;
    return cells * w.count_bytes + intervals * (w.material_bytes + top_bytes);
}

std::vector<uint8_t> encode_header_v2(const HeaderV2 &h)
{
    ByteWriter out;
    out.reserve(STACKS_V2_HEADER_SIZE);
    out.raw(STACKS_MAGIC, sizeof STACKS_MAGIC);
    out.u16(FORMAT_V2_MAJOR);
    out.u16(h.minor);
    out.u32(h.header_size);
    out.u32(h.required);
    out.u32(h.optional);
    write_frame(out, h.frame);
    out.u32(h.materials);
    out.u64(h.intervals);
    out.u32(h.block_size);
    out.u32(h.block_size);
    out.u8(h.widths.count_bytes);
    out.u8(h.widths.material_bytes);
    out.u8(uint8_t(h.widths.tops));
    out.u8(h.compression);
    out.u64(h.materials_at);
    out.u64(h.table_at);
    out.u64(h.end);
    out.u32(h.crc_materials);
    out.u32(h.crc_table);
    out.u32(crc32_of(out.bytes().data(), out.size()));
    SBRT_CHECK_EQ(out.size(), size_t(STACKS_V2_HEADER_SIZE), "format v2 header");
    return std::move(out.bytes());
}

namespace {

/// Reads the header by prefix: the fields of 2.0, then skips what a later
/// minor version put before the header checksum.
HeaderV2 decode_header(const uint8_t *data, size_t size, const std::string &what)
{
    ByteReader in(data, size, what);
    in.seek(sizeof STACKS_MAGIC);
    if (in.u16() != FORMAT_V2_MAJOR)
        fail(what, ": not a format 2 stacks file");
    HeaderV2 h;
    h.minor = in.u16();
    h.header_size = in.u32();
    if (h.header_size < STACKS_V2_HEADER_SIZE || h.header_size > (1u << 20))
        fail(what, ": header size ", h.header_size, " not in ",
             STACKS_V2_HEADER_SIZE, "..", 1u << 20, " (corrupt file)");
    if (size < h.header_size)
        fail(what, ": truncated header (", size, " of ", h.header_size, " bytes)");
    if (crc32_of(data, h.header_size - 4) !=
        ByteReader(data + h.header_size - 4, 4, what).u32())
        fail(what, ": header checksum mismatch (corrupt file)");
    h.required = in.u32();
    h.optional = in.u32();
    if (h.required & ~V2_KNOWN_REQUIRED_FEATURES)
        fail(what, ": written by a newer r3.sbrt (format 2.", h.minor,
             ", features 0x", std::hex, h.required & ~V2_KNOWN_REQUIRED_FEATURES,
             std::dec, " not known here); update r3.sbrt to read it");
    h.frame = read_frame(in, what);
    h.materials = in.u32();
    h.intervals = in.u64();
    h.block_size = in.u32();
    if (in.u32() != h.block_size || h.block_size == 0 || h.block_size > MAX_BLOCK_SIZE)
        fail(what, ": block size not square or not in 1..", MAX_BLOCK_SIZE);
    h.widths.count_bytes = in.u8();
    h.widths.material_bytes = in.u8();
    const uint8_t tops = in.u8();
    h.compression = in.u8();
    if ((h.widths.count_bytes != 1 && h.widths.count_bytes != 2 &&
         h.widths.count_bytes != 4) ||
        (h.widths.material_bytes != 1 && h.widths.material_bytes != 2) ||
        tops > uint8_t(TopEncoding::Float32) || h.compression != COMPRESSION_ZSTD)
        fail(what, ": unknown field widths or compression (corrupt file)");
    h.widths.tops = TopEncoding(tops);
    h.materials_at = in.u64();
    h.table_at = in.u64();
    h.end = in.u64();
    h.crc_materials = in.u32();
    h.crc_table = in.u32();
    return h;
}

} // namespace

StacksV2Layout open_stacks_v2(const uint8_t *data, size_t size, const std::string &what)
{
    if (size < sizeof STACKS_MAGIC + 8 || std::memcmp(data, STACKS_MAGIC, sizeof STACKS_MAGIC) != 0)
        fail(what, ": not an SBRT stacks file (bad magic number)");
    StacksV2Layout out;
    const HeaderV2 &h = out.header = decode_header(data, size, what);
    if (h.materials == 0 || h.materials > MAX_MATERIALS ||
        (h.widths.material_bytes == 1 && h.materials > 0x100))
        fail(what, ": material count ", h.materials, " not in 1..",
             h.widths.material_bytes == 1 ? 0x100 : MAX_MATERIALS);
    if (h.end != size)
        fail(what, ": file has ", size, " bytes, its header describes ", h.end,
             h.end > size ? " (truncated)" : "");
    out.grid = BlockGrid{h.frame.rows, h.frame.cols, int(h.block_size)};
    const BlockGrid &grid = out.grid;
    const uint64_t blocks = uint64_t(grid.block_rows()) * uint64_t(grid.block_cols());
    out.materials_end = h.materials_at + uint64_t(h.materials) * MATERIAL_RECORD_BYTES;
    if (blocks > INT32_MAX || h.materials_at != h.header_size ||
        out.materials_end > h.table_at || h.table_at > size ||
        size - h.table_at != blocks * BLOCK_ENTRY_BYTES)
        fail(what, ": section offsets do not match the counts (corrupt file)");
    if (crc32_of(data + h.materials_at, out.materials_end - h.materials_at) !=
            h.crc_materials ||
        crc32_of(data + h.table_at, size - h.table_at) != h.crc_table)
        fail(what, ": data checksum mismatch (corrupt file)");

    ByteReader in(data, size, what);
    in.seek(h.materials_at);
    out.materials = read_materials(in, h.materials);

    in.seek(h.table_at);
    out.entries.resize(blocks);
    uint64_t total = 0, blocks_end = out.materials_end;
    for (size_t b = 0; b < out.entries.size(); ++b) {
        BlockEntry &e = out.entries[b];
        e.offset = in.u64();
        e.compressed = in.u32();
        e.raw = in.u32();
        e.intervals = in.u32();
        e.crc = in.u32();
        if (e.offset < out.materials_end || e.offset > h.table_at ||
            e.compressed > h.table_at - e.offset ||
            e.raw != raw_block_size(h.widths, grid.cells(int(b)), e.intervals))
            fail(what, ": block ", b, " lies outside the data or has the wrong "
                 "size (corrupt file)");
        total += e.intervals;
        blocks_end = std::max(blocks_end, e.offset + e.compressed);
    }
    if (total != h.intervals)
        fail(what, ": blocks hold ", total, " intervals, header says ", h.intervals);
    // the summaries lie after every block, up to the table
    if (h.optional & V2_OPTIONAL_SUMMARY)
        out.summary_at =
            find_block_summaries(data, blocks_end, h.table_at, out.entries.size(), what);
    return out;
}

} // namespace sbrt
