/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Format v2 of the `stacks` file: streamed writer and
 *            validating block-parallel reader
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/format_v2.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <unistd.h>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "format/stacks_fields.hpp"

namespace sbrt {

namespace {

constexpr uint8_t COMPRESSION_ZSTD = 1;
constexpr size_t BLOCK_ENTRY_BYTES = 24;
constexpr uint32_t MAX_BLOCK_SIZE = 4096;

struct CompressContext {
    void operator()(ZSTD_CCtx *c) const { ZSTD_freeCCtx(c); }
};
struct DecompressContext {
    void operator()(ZSTD_DCtx *c) const { ZSTD_freeDCtx(c); }
};
using CompressorPtr = std::unique_ptr<ZSTD_CCtx, CompressContext>;
using DecompressorPtr = std::unique_ptr<ZSTD_DCtx, DecompressContext>;

/// \brief The blocks of a grid: square tiles of cells, row by row.
struct BlockGrid {
    int rows, cols, size;
    // in 64 bits: rows + size - 1 may pass INT32_MAX
    int block_rows() const { return int((int64_t(rows) + size - 1) / size); }
    int block_cols() const { return int((int64_t(cols) + size - 1) / size); }
    /// At most rows * cols <= 2^31 - 1 (Frame::validate).
    int count() const { return int(int64_t(block_rows()) * block_cols()); }
    int first_row(int block) const { return block / block_cols() * size; }
    int first_col(int block) const { return block % block_cols() * size; }
    int height(int block) const { return std::min(size, rows - first_row(block)); }
    int width(int block) const { return std::min(size, cols - first_col(block)); }
    uint64_t cells(int block) const { return uint64_t(height(block)) * uint64_t(width(block)); }
    /// Calls visit(cell) for the cells of `block` (indices row by row of
    /// the whole grid), in the order the block stores them.
    template <typename Visit>
    void for_each_cell(int block, const Visit &visit) const
    {
        const int r0 = first_row(block), c0 = first_col(block);
        for (int r = r0; r < r0 + height(block); ++r)
            for (int c = c0; c < c0 + width(block); ++c)
                visit(uint64_t(r) * uint64_t(cols) + uint64_t(c));
    }
};

/// \brief One block as stored in the block table.
struct BlockEntry {
    uint64_t offset = 0;
    uint32_t compressed = 0, raw = 0, intervals = 0, crc = 0;
};

uint64_t raw_block_size(const StacksV2Widths &w, uint64_t cells, uint64_t intervals)
{
    const uint64_t top_bytes = w.tops == TopEncoding::VoxelBoundaries ? 2 : 4;
    return cells * w.count_bytes + intervals * (w.material_bytes + top_bytes);
}

/// The uncompressed bytes of one block (counts, materials, tops) into
/// `raw`; returns the block's interval count.
uint32_t encode_block(const Model &model, const BlockGrid &grid, int block,
                      const StacksV2Widths &w, std::vector<uint8_t> &raw)
{
    uint64_t intervals = 0;
    grid.for_each_cell(block, [&](uint64_t cell) { intervals += model.stack_size(cell); });
    raw.resize(raw_block_size(w, grid.cells(block), intervals));
    uint8_t *counts = raw.data();
    uint8_t *materials = counts + grid.cells(block) * w.count_bytes;
    uint8_t *tops = materials + intervals * w.material_bytes;
    const IntervalArray &all = model.intervals();
    grid.for_each_cell(block, [&](uint64_t cell) {
        const StackRange stack = model.stack(cell);
        store_le(counts, stack.size(), w.count_bytes);
        counts += w.count_bytes;
        float below = 0;
        for (uint64_t i = stack.begin; i < stack.end; ++i) {
            const Interval iv = all[i];
            store_le(materials, iv.material, w.material_bytes);
            materials += w.material_bytes;
            if (w.tops == TopEncoding::VoxelBoundaries) {
                store_le(tops, uint32_t(iv.top - below), 2);
                tops += 2;
                below = iv.top;
            }
            else {
                uint32_t bits;
                std::memcpy(&bits, &iv.top, 4);
                store_le(tops, bits, 4); // little-endian on any host
                tops += 4;
            }
        }
    });
    return uint32_t(intervals);
}

/// \brief The fields of a v2 header that a reader needs.
struct HeaderV2 {
    uint16_t minor = FORMAT_V2_MINOR;
    uint32_t header_size = STACKS_V2_HEADER_SIZE;
    uint32_t required = 0, optional = 0;
    Frame frame;
    uint32_t materials = 0;
    uint64_t intervals = 0;
    uint32_t block_size = 0;
    StacksV2Widths widths;
    uint8_t compression = COMPRESSION_ZSTD;
    uint64_t materials_at = 0, table_at = 0, end = 0;
    uint32_t crc_materials = 0, crc_table = 0;
};

std::vector<uint8_t> encode_header(const HeaderV2 &h)
{
    const Frame &f = h.frame;
    ByteWriter out;
    out.reserve(STACKS_V2_HEADER_SIZE);
    out.raw(STACKS_MAGIC, sizeof STACKS_MAGIC);
    out.u16(FORMAT_V2_MAJOR);
    out.u16(h.minor);
    out.u32(h.header_size);
    out.u32(h.required);
    out.u32(h.optional);
    write_frame(out, f);
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

/// Whether `block` holds a cell within one cell of `area` (all, without).
std::vector<char> blocks_meeting(const BlockGrid &grid, const Frame &f,
                                 const std::optional<MapArea> &area)
{
    std::vector<char> wanted(size_t(grid.count()), 1);
    if (!area)
        return wanted;
    // the cells the area touches, one more on every side, clamped
    auto clamp = [](double v, int high) {
        return int(std::max(0.0, std::min(double(high), v)));
    };
    const int first_col = clamp(std::floor((area->west - f.west) / f.ew_res()) - 1, f.cols - 1);
    const int last_col = clamp(std::floor((area->east - f.west) / f.ew_res()) + 1, f.cols - 1);
    const int first_row = clamp(std::floor((f.north - area->north) / f.ns_res()) - 1, f.rows - 1);
    const int last_row = clamp(std::floor((f.north - area->south) / f.ns_res()) + 1, f.rows - 1);
    const bool outside = area->west > f.east || area->east < f.west ||
                         area->south > f.north || area->north < f.south;
    for (int b = 0; b < grid.count(); ++b)
        wanted[size_t(b)] = !outside && grid.first_col(b) <= last_col &&
                            grid.first_col(b) + grid.width(b) > first_col &&
                            grid.first_row(b) <= last_row &&
                            grid.first_row(b) + grid.height(b) > first_row;
    return wanted;
}

uint64_t physical_memory()
{
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) : UINT64_MAX;
}

/// Decompresses the first `out_size` bytes of a zstd frame.
void decompress_prefix(ZSTD_DCtx *context, const uint8_t *src, size_t src_size,
                       uint8_t *out, size_t out_size, const std::string &what)
{
    ZSTD_DCtx_reset(context, ZSTD_reset_session_only);
    ZSTD_inBuffer in = {src, src_size, 0};
    ZSTD_outBuffer o = {out, out_size, 0};
    while (o.pos < o.size) {
        const size_t before_in = in.pos, before_out = o.pos;
        const size_t r = ZSTD_decompressStream(context, &o, &in);
        if (ZSTD_isError(r))
            fail(what, ": ", ZSTD_getErrorName(r), " (corrupt file)");
        if (o.pos < o.size && (r == 0 || (in.pos == before_in && o.pos == before_out)))
            fail(what, ": compressed block ends early (corrupt file)");
    }
}

} // namespace

StacksV2Widths widths_for(const Model &model)
{
    StacksV2Widths w;
    const uint32_t max_stack = model.index().max_size();
    w.count_bytes = max_stack <= 0xff ? 1 : max_stack <= 0xffff ? 2 : 4;
    w.material_bytes = model.materials().size() <= 0x100 ? 1 : 2;
    const IntervalArray &intervals = model.intervals();
    bool voxel_tops = model.frame().depths <= 0xffff;
    for (size_t i = 0; voxel_tops && !intervals.is_compact() && i < intervals.size(); ++i)
        voxel_tops = intervals[i].top == std::floor(intervals[i].top);
    w.tops = voxel_tops ? TopEncoding::VoxelBoundaries : TopEncoding::Float32;
    return w;
}

void write_stacks_v2(ByteSink &sink, const Model &model, const StacksV2Options &options)
{
    const Frame &f = model.frame();
    if (options.block_size < 1 || uint32_t(options.block_size) > MAX_BLOCK_SIZE)
        fail("write_stacks_v2: block size ", options.block_size, " not in 1..",
             MAX_BLOCK_SIZE);
    HeaderV2 h;
    h.optional = options.optional_features;
    h.frame = f;
    h.materials = uint32_t(model.materials().size());
    h.intervals = model.intervals().size();
    h.block_size = uint32_t(options.block_size);
    h.widths = widths_for(model);
    const uint64_t start = sink.size();
    sink.append(std::vector<uint8_t>(STACKS_V2_HEADER_SIZE).data(), STACKS_V2_HEADER_SIZE);

    ByteWriter materials;
    write_materials(materials, model.materials());
    h.materials_at = STACKS_V2_HEADER_SIZE;
    h.crc_materials = crc32_of(materials.bytes().data(), materials.size());
    sink.append(materials.bytes().data(), materials.size());

    // blocks compressed in parallel a batch at a time, written in order
    const BlockGrid grid{f.rows, f.cols, options.block_size};
    const unsigned threads = thread_count(options.threads);
    const int batch = int(threads) * 4;
    std::vector<BlockEntry> entries(size_t(grid.count()));
    std::vector<std::vector<uint8_t>> compressed(static_cast<size_t>(batch));
    for (int first = 0; first < grid.count(); first += batch) {
        const int last = std::min(grid.count(), first + batch);
        for_each_row(first, last, threads, [&](int block) {
            std::vector<uint8_t> raw;
            const uint32_t intervals = encode_block(model, grid, block, h.widths, raw);
            if (raw.size() > UINT32_MAX / 2)
                fail("write_stacks_v2: block ", block, " holds ", raw.size(),
                     " bytes; write smaller blocks");
            std::vector<uint8_t> &out = compressed[size_t(block - first)];
            out.resize(ZSTD_compressBound(raw.size()));
            const CompressorPtr context(ZSTD_createCCtx());
            const size_t n = ZSTD_compressCCtx(context.get(), out.data(), out.size(),
                                               raw.data(), raw.size(), options.zstd_level);
            if (ZSTD_isError(n))
                fail("write_stacks_v2: zstd: ", ZSTD_getErrorName(n));
            out.resize(n);
            BlockEntry &e = entries[size_t(block)];
            e.compressed = uint32_t(n);
            e.raw = uint32_t(raw.size());
            e.crc = crc32_of(out.data(), n);
            e.intervals = intervals;
        });
        for (int block = first; block < last; ++block) {
            const std::vector<uint8_t> &out = compressed[size_t(block - first)];
            entries[size_t(block)].offset = sink.size() - start;
            sink.append(out.data(), out.size());
        }
    }
    ByteWriter table;
    for (const BlockEntry &e : entries) {
        table.u64(e.offset);
        table.u32(e.compressed);
        table.u32(e.raw);
        table.u32(e.intervals);
        table.u32(e.crc);
    }
    h.table_at = sink.size() - start;
    h.crc_table = crc32_of(table.bytes().data(), table.size());
    sink.append(table.bytes().data(), table.size());
    h.end = sink.size() - start;
    const std::vector<uint8_t> header = encode_header(h);
    sink.overwrite(start, header.data(), header.size());
}

std::vector<uint8_t> encode_stacks_v2(const Model &model, const StacksV2Options &options)
{
    MemorySink sink;
    write_stacks_v2(sink, model, options);
    return std::move(sink.bytes());
}

Model decode_stacks_v2(const uint8_t *data, size_t size, const std::string &what,
                       const ReadOptions &options)
{
    const unsigned threads = options.threads;
    if (size < sizeof STACKS_MAGIC + 8 || std::memcmp(data, STACKS_MAGIC, sizeof STACKS_MAGIC) != 0)
        fail(what, ": not an SBRT stacks file (bad magic number)");
    const HeaderV2 h = decode_header(data, size, what);
    const Frame &f = h.frame;
    if (h.materials == 0 || h.materials > MAX_MATERIALS ||
        (h.widths.material_bytes == 1 && h.materials > 0x100))
        fail(what, ": material count ", h.materials, " not in 1..",
             h.widths.material_bytes == 1 ? 0x100 : MAX_MATERIALS);
    if (h.end != size)
        fail(what, ": file has ", size, " bytes, its header describes ", h.end,
             h.end > size ? " (truncated)" : "");
    const BlockGrid grid{f.rows, f.cols, int(h.block_size)};
    const uint64_t blocks = uint64_t(grid.block_rows()) * uint64_t(grid.block_cols());
    const uint64_t materials_end = h.materials_at + uint64_t(h.materials) * MATERIAL_RECORD_BYTES;
    if (blocks > INT32_MAX || h.materials_at != h.header_size ||
        materials_end > h.table_at || h.table_at > size ||
        size - h.table_at != blocks * BLOCK_ENTRY_BYTES)
        fail(what, ": section offsets do not match the counts (corrupt file)");
    if (crc32_of(data + h.materials_at, materials_end - h.materials_at) !=
            h.crc_materials ||
        crc32_of(data + h.table_at, size - h.table_at) != h.crc_table)
        fail(what, ": data checksum mismatch (corrupt file)");

    ByteReader in(data, size, what);
    in.seek(h.materials_at);
    std::vector<Material> materials = read_materials(in, h.materials);

    in.seek(h.table_at);
    std::vector<BlockEntry> entries(blocks);
    uint64_t total = 0;
    for (size_t b = 0; b < entries.size(); ++b) {
        BlockEntry &e = entries[b];
        e.offset = in.u64();
        e.compressed = in.u32();
        e.raw = in.u32();
        e.intervals = in.u32();
        e.crc = in.u32();
        if (e.offset < materials_end || e.offset > h.table_at ||
            e.compressed > h.table_at - e.offset ||
            e.raw != raw_block_size(h.widths, grid.cells(int(b)), e.intervals))
            fail(what, ": block ", b, " lies outside the data or has the wrong "
                 "size (corrupt file)");
        total += e.intervals;
    }
    if (total != h.intervals)
        fail(what, ": blocks hold ", total, " intervals, header says ", h.intervals);
    std::vector<char> wanted = blocks_meeting(grid, f, options.area);
    // with points: only the blocks that hold one, and of them only the
    // points' cells where the SBRT has no property channels (their values
    // lie by the spans of every column of a block)
    std::vector<char> keep;
    if (options.points) {
        const bool whole_blocks = (h.optional & V2_OPTIONAL_CHANNELS) != 0;
        keep.assign(f.cells(), 0);
        std::vector<char> holds(wanted.size(), 0);
        const int block_cols = grid.block_cols();
        for (const auto &[x, y] : *options.points)
            if (const std::optional<GridCell> c = cell_of_point(f, x, y)) {
                keep[uint64_t(c->row) * uint64_t(f.cols) + uint64_t(c->col)] = 1;
                holds[size_t(c->row / grid.size) * size_t(block_cols) + size_t(c->col / grid.size)] = 1;
            }
        for (size_t b = 0; b < wanted.size(); ++b)
            wanted[b] = wanted[b] && holds[b];
        if (whole_blocks)
            keep.clear();
    }
    const auto decoded = [&](uint64_t cell) { return keep.empty() || keep[cell]; };
    uint64_t wanted_intervals = 0, wanted_blocks = 0;
    for (size_t b = 0; b < entries.size(); ++b)
        if (wanted[b]) {
            wanted_intervals += entries[b].intervals;
            ++wanted_blocks;
        }
    if (options.report)
        *options.report = ReadReport{blocks, wanted_blocks};
    // voxel boundaries within 16 bits are held as 4-byte intervals
    const bool compact =
        h.widths.tops == TopEncoding::VoxelBoundaries && voxel_tops_fit_compact(f.depths);
    const uint64_t limit = options.memory_limit ? options.memory_limit : physical_memory();
    // pass 1's sizes (4 bytes a cell) beside the index it builds, the
    // points' mask; the intervals of the wanted blocks (with points only
    // the points' own, known after pass 1)
    const double interval_bytes = compact ? sizeof(CompactInterval) : sizeof(Interval);
    const auto check_memory = [&](uint64_t intervals) {
        const double needed = double(f.cells()) * (4 + h.widths.count_bytes + 0.5) +
                              double(keep.size()) + double(intervals) * interval_bytes;
        if (needed > double(limit))
            fail(what, ": the model needs ", std::ceil(needed / (1 << 20)), " MiB of "
                 "memory, more than the ", limit >> 20, " MiB available");
    };
    check_memory(keep.empty() ? wanted_intervals : 0);

    // pass 1: each block's counts (the head of its frame) give the index
    std::vector<uint32_t> sizes(f.cells(), 0);
    for_each_row(int(blocks), threads, [&](int block) {
        if (!wanted[size_t(block)])
            return;
        const BlockEntry &e = entries[size_t(block)];
        const uint8_t *src = data + e.offset;
        const std::string where = what + " block " + std::to_string(block);
        if (crc32_of(src, e.compressed) != e.crc)
            fail(where, ": checksum mismatch (corrupt file)");
        const size_t count_bytes = size_t(grid.cells(block)) * h.widths.count_bytes;
        std::vector<uint8_t> counts(count_bytes);
        const DecompressorPtr context(ZSTD_createDCtx());
        decompress_prefix(context.get(), src, e.compressed, counts.data(),
                          count_bytes, where);
        uint64_t sum = 0;
        const uint8_t *p = counts.data();
        grid.for_each_cell(block, [&](uint64_t cell) {
            const uint64_t n = load_le(p, h.widths.count_bytes);
            p += h.widths.count_bytes;
            sizes[cell] = decoded(cell) ? uint32_t(n) : 0;
            sum += n;
        });
        if (sum != e.intervals)
            fail(where, ": stack sizes sum to ", sum, ", block table says ",
                 e.intervals, " (corrupt file)");
    });
    StackIndex index = StackIndex::from_sizes(sizes.data(), f.cells());
    std::vector<uint32_t>().swap(sizes);
    if (!keep.empty())
        check_memory(index.total());

    // pass 2: each block's intervals into place, in the kind held (with
    // points, the other cells' intervals skipped)
    Intervals wide(compact ? 0 : index.total());
    CompactIntervals packed(compact ? index.total() : 0);
    const uint64_t top_bytes = h.widths.tops == TopEncoding::VoxelBoundaries ? 2 : 4;
    for_each_row(int(blocks), threads, [&](int block) {
        if (!wanted[size_t(block)])
            return;
        const BlockEntry &e = entries[size_t(block)];
        const std::string where = what + " block " + std::to_string(block);
        std::vector<uint8_t> raw(e.raw);
        const DecompressorPtr context(ZSTD_createDCtx());
        const size_t n = ZSTD_decompressDCtx(context.get(), raw.data(), raw.size(),
                                             data + e.offset, e.compressed);
        if (ZSTD_isError(n) || n != raw.size())
            fail(where, ": ", ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size",
                 " (corrupt file)");
        const uint8_t *count = raw.data();
        const uint8_t *material = raw.data() + grid.cells(block) * h.widths.count_bytes;
        const uint8_t *top = material + uint64_t(e.intervals) * h.widths.material_bytes;
        grid.for_each_cell(block, [&](uint64_t cell) {
            const uint64_t stack_size = load_le(count, h.widths.count_bytes);
            count += h.widths.count_bytes;
            if (!decoded(cell)) {
                material += stack_size * h.widths.material_bytes;
                top += stack_size * top_bytes;
                return;
            }
            const StackRange stack = index.range(cell);
            uint32_t below = 0;
            for (uint64_t i = stack.begin; i < stack.end; ++i) {
                const uint32_t m = uint32_t(load_le(material, h.widths.material_bytes));
                material += h.widths.material_bytes;
                if (compact) {
                    below += uint32_t(load_le(top, 2));
                    top += 2;
                    if (below > uint32_t(f.depths))
                        fail(where, ": an interval top lies above the model's ",
                             f.depths, " depths (corrupt file)");
                    packed[i] = voxel_interval<CompactInterval>(m, below);
                }
                else if (h.widths.tops == TopEncoding::VoxelBoundaries) {
                    below += uint32_t(load_le(top, 2)); // a wrap gives tops validate() rejects
                    wide[i] = {m, float(below)};
                    top += 2;
                }
                else {
                    const uint32_t bits = uint32_t(load_le(top, 4));
                    wide[i].material = m;
                    std::memcpy(&wide[i].top, &bits, 4);
                    top += 4;
                }
            }
        });
    });
    IntervalArray intervals = compact ? IntervalArray(std::move(packed))
                                      : IntervalArray(std::move(wide));
    return validated_model(f, std::move(materials), std::move(index),
                           std::move(intervals), what);
}

} // namespace sbrt
