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
#include <optional>
#include <unistd.h>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "format/block_summary.hpp"
#include "format/stacks_fields.hpp"
#include "format/stacks_v2_layout.hpp"
#include "format/stacks_writer.hpp"

namespace sbrt {

namespace {

struct DecompressContext {
    void operator()(ZSTD_DCtx *c) const { ZSTD_freeDCtx(c); }
};
using DecompressorPtr = std::unique_ptr<ZSTD_DCtx, DecompressContext>;

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
    StacksWriter writer(model.frame(), options);
    writer.add_rows(model);
    writer.finish(sink, model.materials());
}

std::vector<uint8_t> encode_stacks_v2(const Model &model, const StacksV2Options &options)
{
    MemorySink sink;
    write_stacks_v2(sink, model, options);
    return std::move(sink.bytes());
}

double decoded_bytes(uint64_t cells, uint64_t intervals, unsigned count_bytes,
                     unsigned record_bytes)
{
    return double(cells) * (4 + count_bytes + 0.5) + double(intervals) * record_bytes;
}

Frame frame_rows(const Frame &frame, int first, int count)
{
    if (first < 0 || count < 1 || first > frame.rows - count)
        fail("rows ", first, " to ", int64_t(first) + count - 1, " are not rows of a model of ",
             frame.rows, " rows");
    Frame out = frame;
    out.rows = count;
    // the frame's own edges where the rows reach them (no rounding there)
    const double height = frame.north - frame.south;
    if (first > 0)
        out.north = frame.north - height * first / frame.rows;
    if (first + count < frame.rows)
        out.south = frame.north - height * (first + count) / frame.rows;
    return out;
}

namespace {

/// Which blocks a read decodes, and of their cells which.
struct CellSelection {
    std::vector<char> wanted; ///< a flag a block
    /// a flag a cell of the file's frame, with points only; empty: all
    std::vector<char> keep;
    uint64_t first_cell = 0, end_cell = 0; ///< the rows' cells in the file
    bool decoded(uint64_t cell) const
    {
        return cell >= first_cell && cell < end_cell && (keep.empty() || keep[cell]);
    }
};

/// Drops the blocks with none of `rows`' rows from `wanted`.
void keep_rows(std::vector<char> &wanted, const BlockGrid &grid, const ReadOptions::Rows &rows)
{
    for (size_t b = 0; b < wanted.size(); ++b) {
        const int top_row = grid.first_row(int(b));
        wanted[b] = wanted[b] && top_row < rows.first + rows.count &&
                    top_row + grid.height(int(b)) > rows.first;
    }
}

/// Drops the blocks that hold none of `points` from `wanted`; returns
/// the points' cells, or nothing (all cells of the blocks) where the SBRT
/// has property channels (their values lie by the spans of every column
/// of a block).
std::vector<char> keep_points(std::vector<char> &wanted, const StacksV2Layout &layout,
                              const std::vector<std::array<double, 2>> &points)
{
    const HeaderV2 &h = layout.header;
    const Frame &f = h.frame;
    const BlockGrid &grid = layout.grid;
    const bool whole_blocks = (h.optional & V2_OPTIONAL_CHANNELS) != 0;
    std::vector<char> keep(f.cells(), 0);
    std::vector<char> holds(wanted.size(), 0);
    const int block_cols = grid.block_cols();
    for (const auto &[x, y] : points)
        if (const std::optional<GridCell> c = cell_of_point(f, x, y)) {
            keep[uint64_t(c->row) * uint64_t(f.cols) + uint64_t(c->col)] = 1;
            holds[size_t(c->row / grid.size) * size_t(block_cols) + size_t(c->col / grid.size)] = 1;
        }
    for (size_t b = 0; b < wanted.size(); ++b)
        wanted[b] = wanted[b] && holds[b];
    if (whole_blocks)
        keep.clear();
    return keep;
}

/// The blocks of `wanted` (those meeting the area) and cells a read
/// decodes: the model `out` of options' rows, with points only the
/// blocks that hold one.
CellSelection select_cells(std::vector<char> wanted, const StacksV2Layout &layout,
                       const ReadOptions &options, const Frame &out)
{
    CellSelection s;
    s.wanted = std::move(wanted);
    const Frame &f = layout.header.frame;
    s.first_cell = options.rows ? uint64_t(options.rows->first) * uint64_t(f.cols) : 0;
    s.end_cell = s.first_cell + out.cells();
    if (options.rows)
        keep_rows(s.wanted, layout.grid, *options.rows);
    if (options.points)
        s.keep = keep_points(s.wanted, layout, *options.points);
    return s;
}

/// The intervals the wanted blocks hold; the report filled where asked.
uint64_t count_wanted(const std::vector<BlockEntry> &entries, const std::vector<char> &wanted,
                      ReadReport *report)
{
    uint64_t wanted_intervals = 0, wanted_blocks = 0;
    for (size_t b = 0; b < entries.size(); ++b)
        if (wanted[b]) {
            wanted_intervals += entries[b].intervals;
            ++wanted_blocks;
        }
    if (report)
        *report = ReadReport{entries.size(), wanted_blocks};
    return wanted_intervals;
}

/// What a read may take: pass 1's sizes (4 bytes a cell) beside the
/// index it builds, the points' mask; the intervals of the wanted blocks
/// (with points only the points' own, known after pass 1).
struct MemoryBudget {
    const std::string &what;
    uint64_t cells;
    unsigned count_bytes, interval_bytes;
    size_t mask_bytes;
    uint64_t limit;

    void check(uint64_t intervals) const
    {
        const double needed =
            decoded_bytes(cells, intervals, count_bytes, interval_bytes) + double(mask_bytes);
        if (needed > double(limit))
            fail(what, ": the model needs ", std::ceil(needed / (1 << 20)), " MiB of "
                 "memory, more than the ", limit >> 20, " MiB available");
    }
};

/// Pass 1: each wanted block's counts (the head of its frame), checked
/// against the block table, give the index of the `cells` selected cells.
StackIndex read_stack_index(const uint8_t *data, const StacksV2Layout &layout,
                            const CellSelection &s, uint64_t cells, unsigned threads,
                            const std::string &what)
{
    const BlockGrid &grid = layout.grid;
    const std::vector<BlockEntry> &entries = layout.entries;
    const unsigned width = layout.header.widths.count_bytes;
    std::vector<uint32_t> sizes(cells, 0);
    for_each_row(int(entries.size()), threads, [&](int block) {
        if (!s.wanted[size_t(block)])
            return;
        const BlockEntry &e = entries[size_t(block)];
        const uint8_t *src = data + e.offset;
        const std::string where = what + " block " + std::to_string(block);
        if (crc32_of(src, e.compressed) != e.crc)
            fail(where, ": checksum mismatch (corrupt file)");
        const size_t count_bytes = size_t(grid.cells(block)) * width;
        std::vector<uint8_t> counts(count_bytes);
        const DecompressorPtr context(ZSTD_createDCtx());
        decompress_prefix(context.get(), src, e.compressed, counts.data(), count_bytes, where);
        uint64_t sum = 0;
        const uint8_t *p = counts.data();
        grid.for_each_cell(block, [&](uint64_t cell) {
            const uint64_t n = load_le(p, width);
            p += width;
            if (s.decoded(cell))
                sizes[cell - s.first_cell] = uint32_t(n);
            sum += n;
        });
        if (sum != e.intervals)
            fail(where, ": stack sizes sum to ", sum, ", block table says ",
                 e.intervals, " (corrupt file)");
    });
    return StackIndex::from_sizes(sizes.data(), cells);
}

/// A block's whole frame, `e.raw` bytes exactly.
using RawBlock = std::vector<uint8_t, UnfilledAllocator<uint8_t>>;

RawBlock decompress_block(const uint8_t *data, const BlockEntry &e, const std::string &where)
{
    RawBlock raw(e.raw); // every byte written by the decompressor
    // one context a thread, kept: a paged model decompresses block after
    // block on the tracer's threads (a context made each time showed in a
    // national view's profile)
    thread_local const DecompressorPtr context(ZSTD_createDCtx());
    const size_t n = ZSTD_decompressDCtx(context.get(), raw.data(), raw.size(),
                                         data + e.offset, e.compressed);
    if (ZSTD_isError(n) || n != raw.size())
        fail(where, ": ", ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size",
             " (corrupt file)");
    return raw;
}

/// Pass 2's intervals, in the kind held: `packed` where voxel boundaries
/// fit 16 bits (`compact`), else `wide`; sized by the index.
struct IntervalDecoder {
    const StacksV2Widths &widths;
    int depths;
    bool compact;
    Intervals wide;
    CompactIntervals packed;

    /// The intervals of `stack` from the records at `material` and
    /// `top`, both moved past them.
    void decode(const StackRange &stack, const uint8_t *&material, const uint8_t *&top,
                const std::string &where)
    {
        uint32_t below = 0;
        for (uint64_t i = stack.begin; i < stack.end; ++i) {
            const uint32_t m = uint32_t(load_le(material, widths.material_bytes));
            material += widths.material_bytes;
            if (compact) {
                below += uint32_t(load_le(top, 2));
                top += 2;
                if (below > uint32_t(depths))
                    fail(where, ": an interval top lies above the model's ", depths,
                         " depths (corrupt file)");
                packed[i] = voxel_interval<CompactInterval>(m, below);
            }
            else if (widths.tops == TopEncoding::VoxelBoundaries) {
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
    }

    IntervalArray take()
    {
        return compact ? IntervalArray(std::move(packed)) : IntervalArray(std::move(wide));
    }
};

/// Pass 2: each wanted block's intervals into place (with points, the
/// other cells' intervals skipped).
void decode_intervals(const uint8_t *data, const StacksV2Layout &layout, const CellSelection &s,
                      const StackIndex &index, IntervalDecoder &out, unsigned threads,
                      const std::string &what)
{
    const BlockGrid &grid = layout.grid;
    const StacksV2Widths &w = layout.header.widths;
    const uint64_t top_bytes = w.tops == TopEncoding::VoxelBoundaries ? 2 : 4;
    for_each_row(int(layout.entries.size()), threads, [&](int block) {
        if (!s.wanted[size_t(block)])
            return;
        const BlockEntry &e = layout.entries[size_t(block)];
        const std::string where = what + " block " + std::to_string(block);
        const RawBlock raw = decompress_block(data, e, where);
        const uint8_t *count = raw.data();
        const uint8_t *material = raw.data() + grid.cells(block) * w.count_bytes;
        const uint8_t *top = material + uint64_t(e.intervals) * w.material_bytes;
        grid.for_each_cell(block, [&](uint64_t cell) {
            const uint64_t stack_size = load_le(count, w.count_bytes);
            count += w.count_bytes;
            if (!s.decoded(cell)) {
                material += stack_size * w.material_bytes;
                top += stack_size * top_bytes;
                return;
            }
            out.decode(index.range(cell - s.first_cell), material, top, where);
        });
    });
}

/// A block's stacks of voxel-boundary tops held compact, checked while
/// decoded for what validate_stacks checks (material indices in range,
/// tops rising within the depths, no two adjacent intervals of one
/// material, no trailing EMPTY): one pass, no branch on the widths per
/// interval. False where a check fails (the generic path then says which).
template <unsigned MaterialBytes>
bool decode_compact_checked(const uint8_t *material, const uint8_t *top,
                            const std::vector<uint32_t> &sizes, uint32_t material_count,
                            uint32_t depths, CompactInterval *out)
{
    bool bad = false;
    for (const uint32_t n : sizes) {
        uint32_t below = 0, previous = UINT32_MAX;
        for (uint32_t i = 0; i < n; ++i, material += MaterialBytes, top += 2) {
            uint32_t m = material[0];
            if constexpr (MaterialBytes == 2)
                m |= uint32_t(material[1]) << 8;
            const uint32_t delta = uint32_t(top[0]) | uint32_t(top[1]) << 8;
            below += delta;
            bad |= (m >= material_count) | (delta == 0) | (below > depths) | (m == previous);
            previous = m;
            *out++ = {uint16_t(m), uint16_t(below)};
        }
        bad |= n != 0 && previous == EMPTY;
    }
    return !bad;
}

/// The compact intervals of a block on the fast path, where its widths
/// allow and every check holds; nothing otherwise.
std::optional<IntervalArray> fast_compact_block(const uint8_t *material, uint64_t intervals,
                                                const StacksV2Widths &w,
                                                const std::vector<uint32_t> &sizes,
                                                size_t material_count, int depths)
{
    if (w.tops != TopEncoding::VoxelBoundaries || !voxel_tops_fit_compact(depths) ||
        (w.material_bytes != 1 && w.material_bytes != 2))
        return std::nullopt;
    CompactIntervals out(intervals);
    const uint8_t *top = material + intervals * w.material_bytes;
    const bool sound =
        w.material_bytes == 1
            ? decode_compact_checked<1>(material, top, sizes, uint32_t(material_count),
                                        uint32_t(depths), out.data())
            : decode_compact_checked<2>(material, top, sizes, uint32_t(material_count),
                                        uint32_t(depths), out.data());
    if (!sound)
        return std::nullopt;
    return IntervalArray(std::move(out));
}

} // namespace

StackBlock decode_stack_block(const uint8_t *data, const StacksV2Layout &layout, int block,
                              const std::string &what)
{
    const BlockGrid &grid = layout.grid;
    const StacksV2Widths &w = layout.header.widths;
    const BlockEntry &e = layout.entries.at(size_t(block));
    const std::string where = what + " block " + std::to_string(block);
    if (crc32_of(data + e.offset, e.compressed) != e.crc)
        fail(where, ": checksum mismatch (corrupt file)");
    const RawBlock raw = decompress_block(data, e, where);
    StackBlock out;
    out.first_row = grid.first_row(block);
    out.first_col = grid.first_col(block);
    out.rows = grid.height(block);
    out.cols = grid.width(block);
    const uint64_t cells = grid.cells(block);
    // the counts (the table's raw size is that of its cells and intervals)
    std::vector<uint32_t> sizes(cells);
    uint64_t sum = 0;
    const uint8_t *count = raw.data();
    for (uint64_t c = 0; c < cells; ++c, count += w.count_bytes) {
        sizes[c] = uint32_t(load_le(count, w.count_bytes));
        sum += sizes[c];
    }
    if (sum != e.intervals)
        fail(where, ": stack sizes sum to ", sum, ", block table says ", e.intervals,
             " (corrupt file)");
    out.index = StackIndex::from_sizes(sizes.data(), cells);
    const Frame &f = layout.header.frame;
    if (std::optional<IntervalArray> fast = fast_compact_block(
            count, sum, w, sizes, layout.materials.size(), f.depths)) {
        out.intervals = std::move(*fast);
        return out;
    }
    const bool compact =
        w.tops == TopEncoding::VoxelBoundaries && voxel_tops_fit_compact(f.depths);
    IntervalDecoder decoder{w, f.depths, compact, Intervals(compact ? 0 : sum),
                            CompactIntervals(compact ? sum : 0)};
    const uint8_t *material = count;
    const uint8_t *top = material + sum * w.material_bytes;
    for (uint64_t c = 0; c < cells; ++c)
        decoder.decode(out.index.range(c), material, top, where);
    out.intervals = decoder.take().packed();
    Frame block_frame = f; // its cells; the depths bound the tops
    block_frame.rows = out.rows;
    block_frame.cols = out.cols;
    try {
        validate_stacks(block_frame, out.index, out.intervals, layout.materials.size(), 1);
    }
    catch (const Error &error) {
        fail(where, ": ", error.what());
    }
    return out;
}

Model decode_stacks_v2(const uint8_t *data, size_t size, const std::string &what,
                       const ReadOptions &options)
{
    // header, materials and block table checked; the 2.1 summaries are
    // not needed to decode
    StacksV2Layout layout = open_stacks_v2(data, size, what);
    const HeaderV2 &h = layout.header;
    const Frame &f = h.frame;
    std::vector<char> wanted = blocks_meeting(layout.grid, f, options.area);
    // rows=: the model of those rows alone (all of them without)
    const Frame out = options.rows ? frame_rows(f, options.rows->first, options.rows->count) : f;
    const CellSelection s = select_cells(std::move(wanted), layout, options, out);
    const uint64_t wanted_intervals = count_wanted(layout.entries, s.wanted, options.report);
    // voxel boundaries within 16 bits are held as 4-byte intervals
    const bool compact =
        h.widths.tops == TopEncoding::VoxelBoundaries && voxel_tops_fit_compact(f.depths);
    const unsigned interval_bytes = compact ? sizeof(CompactInterval) : sizeof(Interval);
    const MemoryBudget budget{what, out.cells(), h.widths.count_bytes, interval_bytes,
                              s.keep.size(),
                              options.memory_limit ? options.memory_limit : physical_memory()};
    budget.check(s.keep.empty() ? wanted_intervals : 0);

    StackIndex index = read_stack_index(data, layout, s, out.cells(), options.threads, what);
    if (!s.keep.empty())
        budget.check(index.total());

    IntervalDecoder decoder{h.widths, f.depths, compact, Intervals(compact ? 0 : index.total()),
                            CompactIntervals(compact ? index.total() : 0)};
    decode_intervals(data, layout, s, index, decoder, options.threads, what);
    IntervalArray intervals = decoder.take();
    return validated_model(out, std::move(layout.materials), std::move(index),
                           std::move(intervals), what);
}

} // namespace sbrt
