/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The stacks file written band by band of rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/stacks_writer.hpp"

#include <algorithm>
#include <cstring>
#include <memory>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

using CompressorPtr = std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)>;

/// The uncompressed bytes of one block (counts, materials, tops) of the
/// cells of `grid` (a grid of `model`'s frame) into `raw`; returns the
/// block's interval count, and leaves in `solid` how many of them are not
/// EMPTY.
uint32_t encode_block(const Model &model, const BlockGrid &grid, int block,
                      const StacksV2Widths &w, std::vector<uint8_t> &raw, uint64_t &solid)
{
    solid = 0;
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
            solid += iv.material != EMPTY;
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

/// The raw block of `cells` cells encoded with `from` as encoded with the
/// wider `to` (count and material fields widened, voxel-boundary tops
/// turned into f32 where `to` asks for them).
std::vector<uint8_t> widen_block(const std::vector<uint8_t> &raw, uint64_t cells,
                                 uint64_t intervals, const StacksV2Widths &from,
                                 const StacksV2Widths &to)
{
    std::vector<uint8_t> out(raw_block_size(to, cells, intervals));
    const uint8_t *counts = raw.data();
    const uint8_t *materials = counts + cells * from.count_bytes;
    const uint8_t *tops = materials + intervals * from.material_bytes;
    uint8_t *out_counts = out.data();
    uint8_t *out_materials = out_counts + cells * to.count_bytes;
    uint8_t *out_tops = out_materials + intervals * to.material_bytes;
    const bool same_tops = from.tops == to.tops;
    for (uint64_t cell = 0; cell < cells; ++cell) {
        const uint64_t count = load_le(counts + cell * from.count_bytes, from.count_bytes);
        store_le(out_counts + cell * to.count_bytes, count, to.count_bytes);
        float below = 0;
        for (uint64_t i = 0; i < count; ++i) {
            store_le(out_materials, load_le(materials, from.material_bytes), to.material_bytes);
            materials += from.material_bytes;
            out_materials += to.material_bytes;
            if (same_tops) {
                const int bytes = from.tops == TopEncoding::VoxelBoundaries ? 2 : 4;
                std::memcpy(out_tops, tops, size_t(bytes));
                tops += bytes;
                out_tops += bytes;
                continue;
            }
            // voxel boundaries to f32 (the only widening of tops)
            below += float(load_le(tops, 2));
            tops += 2;
            uint32_t bits;
            std::memcpy(&bits, &below, 4);
            store_le(out_tops, bits, 4);
            out_tops += 4;
        }
    }
    return out;
}

/// Compresses `raw` as a block: its bytes and its table entry (offset
/// and interval count left to the caller).
void compress_block(const std::vector<uint8_t> &raw, int level, std::vector<uint8_t> &out,
                    BlockEntry &entry)
{
    if (raw.size() > UINT32_MAX / 2)
        fail("write_stacks_v2: a block holds ", raw.size(), " bytes; write smaller blocks");
    out.resize(ZSTD_compressBound(raw.size()));
    const CompressorPtr context(ZSTD_createCCtx(), ZSTD_freeCCtx);
    const size_t n =
        ZSTD_compressCCtx(context.get(), out.data(), out.size(), raw.data(), raw.size(), level);
    if (ZSTD_isError(n))
        fail("write_stacks_v2: zstd: ", ZSTD_getErrorName(n));
    out.resize(n);
    out.shrink_to_fit();
    entry.compressed = uint32_t(n);
    entry.raw = uint32_t(raw.size());
    entry.crc = crc32_of(out.data(), n);
}

/// Whether `a` and `b` encode every field alike.
bool same_widths(const StacksV2Widths &a, const StacksV2Widths &b)
{
    return a.count_bytes == b.count_bytes && a.material_bytes == b.material_bytes &&
           a.tops == b.tops;
}

} // namespace

StacksWriter::StacksWriter(const Frame &frame, const StacksV2Options &options)
    : frame_(frame), options_(options), grid_{frame.rows, frame.cols, options.block_size}
{
    if (options.block_size < 1 || uint32_t(options.block_size) > MAX_BLOCK_SIZE)
        fail("write_stacks_v2: block size ", options.block_size, " not in 1..",
             MAX_BLOCK_SIZE);
    blocks_.resize(size_t(grid_.count()));
    summaries_.resize(options.summary ? size_t(grid_.count()) : 0);
}

void StacksWriter::add_rows(const Model &band)
{
    const Frame &f = band.frame();
    if (f.cols != frame_.cols || f.rows > frame_.rows - rows_done_ ||
        (rows_done_ + f.rows < frame_.rows && f.rows % options_.block_size != 0))
        fail("write_stacks_v2: a band of ", f.rows, " x ", f.cols, " cells at row ",
             rows_done_, " does not fit blocks of ", options_.block_size,
             " cells of a model of ", frame_.rows, " x ", frame_.cols);
    const StacksV2Widths needed = widths_for(band);
    widths_.count_bytes = std::max(widths_.count_bytes, needed.count_bytes);
    if (needed.tops == TopEncoding::Float32)
        widths_.tops = TopEncoding::Float32;
    materials_seen_ = std::max(materials_seen_, band.materials().size());
    widths_.material_bytes = materials_seen_ <= 0x100 ? 1 : 2;

    // the band's blocks, compressed in parallel
    const BlockGrid grid{f.rows, f.cols, options_.block_size};
    const int first = rows_done_ / options_.block_size * grid_.block_cols();
    const StacksV2Widths widths = widths_;
    std::vector<uint64_t> solid(size_t(grid.count())); // of each block
    for_each_row(grid.count(), thread_count(options_.threads), [&](int block) {
        StoredBlock &stored = blocks_[size_t(first + block)];
        std::vector<uint8_t> raw;
        stored.entry.intervals =
            encode_block(band, grid, block, widths, raw, solid[size_t(block)]);
        compress_block(raw, options_.zstd_level, stored.bytes, stored.entry);
        stored.widths = widths;
        if (options_.summary) {
            BlockSummarizer summary(band.materials().size());
            grid.for_each_cell(block, [&](uint64_t cell) { summary.add_stack(band, cell); });
            summaries_[size_t(first + block)] = summary.finish();
        }
    });
    intervals_ += band.intervals().size();
    for (const uint64_t n : solid)
        solid_intervals_ += n;
    rows_done_ += f.rows;
}

void StacksWriter::finish(ByteSink &sink, const std::vector<Material> &materials,
                          uint32_t optional_features)
{
    if (rows_done_ != frame_.rows)
        fail("write_stacks_v2: ", rows_done_, " of the model's ", frame_.rows,
             " rows were given");
    if (materials.size() < materials_seen_)
        fail("write_stacks_v2: a band used ", materials_seen_, " materials, the model has ",
             materials.size());
    StacksV2Widths widths = widths_;
    widths.material_bytes = materials.size() <= 0x100 ? 1 : 2;
    // blocks of bands before a wider one, recompressed as the whole needs
    for_each_row(grid_.count(), thread_count(options_.threads), [&](int block) {
        StoredBlock &stored = blocks_[size_t(block)];
        if (same_widths(stored.widths, widths))
            return;
        std::vector<uint8_t> raw(stored.entry.raw);
        const size_t n = ZSTD_decompress(raw.data(), raw.size(), stored.bytes.data(),
                                         stored.bytes.size());
        if (ZSTD_isError(n) || n != raw.size())
            fail("write_stacks_v2: a block of this writer does not decompress");
        compress_block(widen_block(raw, grid_.cells(block), stored.entry.intervals,
                                   stored.widths, widths),
                       options_.zstd_level, stored.bytes, stored.entry);
        stored.widths = widths;
    });

    HeaderV2 h;
    h.optional = options_.optional_features | optional_features |
                 (options_.summary ? V2_OPTIONAL_SUMMARY : 0);
    h.minor = options_.summary ? FORMAT_V2_MINOR : 0;
    h.frame = frame_;
    h.materials = uint32_t(materials.size());
    h.intervals = intervals_;
    h.block_size = uint32_t(options_.block_size);
    h.widths = widths;
    const uint64_t start = sink.size();
    sink.append(std::vector<uint8_t>(STACKS_V2_HEADER_SIZE).data(), STACKS_V2_HEADER_SIZE);

    ByteWriter material_bytes;
    write_materials(material_bytes, materials);
    h.materials_at = STACKS_V2_HEADER_SIZE;
    h.crc_materials = crc32_of(material_bytes.bytes().data(), material_bytes.size());
    sink.append(material_bytes.bytes().data(), material_bytes.size());

    ByteWriter table;
    for (StoredBlock &stored : blocks_) {
        stored.entry.offset = sink.size() - start;
        sink.append(stored.bytes.data(), stored.bytes.size());
        stored.bytes = {};
        table.u64(stored.entry.offset);
        table.u32(stored.entry.compressed);
        table.u32(stored.entry.raw);
        table.u32(stored.entry.intervals);
        table.u32(stored.entry.crc);
    }
    if (options_.summary) {
        const std::vector<uint8_t> section = encode_block_summaries(summaries_);
        sink.append(section.data(), section.size());
    }
    h.table_at = sink.size() - start;
    h.crc_table = crc32_of(table.bytes().data(), table.size());
    sink.append(table.bytes().data(), table.size());
    h.end = sink.size() - start;
    const std::vector<uint8_t> header = encode_header_v2(h);
    sink.overwrite(start, header.data(), header.size());
}

} // namespace sbrt
