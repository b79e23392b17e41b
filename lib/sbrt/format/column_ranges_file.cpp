/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `ranges` member of an SBRT
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/column_ranges_file.hpp"

#include <cstring>
#include <memory>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "format/stacks_v2_layout.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

namespace {

constexpr char MAGIC[8] = {'S', 'B', 'R', 'T', 'R', 'N', 'G', '1'};
constexpr size_t HEADER_BYTES = 8 + 3 * 4 + 8 + 8 + 4 + 8 + 4;
constexpr uint32_t U16_PAIRS = 0, F32_PAIRS = 1;
constexpr uint16_t EMPTY_LOW = 0xffff;

/// Whether a range fits a u16 pair exactly (voxel boundaries).
bool fits_u16(const ZRange &r)
{
    return r.empty() || (r.low >= 0 && r.high < float(EMPTY_LOW) &&
                         float(uint16_t(r.low)) == r.low && float(uint16_t(r.high)) == r.high);
}

void append_range(ByteWriter &raw, const ZRange &r, uint32_t encoding)
{
    if (encoding == U16_PAIRS) {
        raw.u16(r.empty() ? EMPTY_LOW : uint16_t(r.low));
        raw.u16(r.empty() ? 0 : uint16_t(r.high));
    }
    else {
        raw.f32(r.empty() ? 1.0f : r.low);
        raw.f32(r.empty() ? 0.0f : r.high);
    }
}

/// `raw` zstd-compressed (level 3) as one frame, streamed into a vector
/// that grows by what it holds, not by the compression bound.
std::vector<uint8_t> compressed(const std::vector<uint8_t> &raw)
{
    const std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> context(ZSTD_createCCtx(),
                                                                      ZSTD_freeCCtx);
    ZSTD_CCtx_setParameter(context.get(), ZSTD_c_compressionLevel, 3);
    ZSTD_CCtx_setPledgedSrcSize(context.get(), raw.size());
    std::vector<uint8_t> out;
    std::vector<uint8_t> chunk(ZSTD_CStreamOutSize());
    ZSTD_inBuffer in = {raw.data(), raw.size(), 0};
    for (;;) {
        ZSTD_outBuffer o = {chunk.data(), chunk.size(), 0};
        const size_t left = ZSTD_compressStream2(context.get(), &o, &in, ZSTD_e_end);
        if (ZSTD_isError(left))
            fail("encode_column_ranges: zstd: ", ZSTD_getErrorName(left));
        out.insert(out.end(), chunk.begin(), chunk.begin() + ptrdiff_t(o.pos));
        if (left == 0)
            return out;
    }
}

} // namespace

StacksStamp stamp_of(const HeaderV2 &h)
{
    StacksStamp stamp;
    stamp.end = h.end;
    stamp.intervals = h.intervals;
    stamp.table_crc = h.crc_table;
    return stamp;
}

StacksStamp stacks_stamp(const uint8_t *data, size_t size, const std::string &what)
{
    return stamp_of(open_stacks_v2(data, size, what).header);
}

ColumnRangesEncoder::ColumnRangesEncoder(const Frame &frame) : frame_(frame)
{
    ranges_.reserve(size_t(frame.cells()) * 4); // u16 pairs, as voxel models take
}

void ColumnRangesEncoder::add(const std::vector<ZRange> &ranges)
{
    if (cells_ + ranges.size() > frame_.cells())
        fail("encode_column_ranges: more ranges than the frame's ", frame_.cells(), " cells");
    for (const ZRange &r : ranges) {
        if (encoding_ == U16_PAIRS && !fits_u16(r)) {
            // the rest, and those before, as f32 pairs
            ByteWriter wide;
            for (size_t at = 0; at < ranges_.size(); at += 4) {
                const uint16_t low = uint16_t(load_le(ranges_.bytes().data() + at, 2));
                const uint16_t high = uint16_t(load_le(ranges_.bytes().data() + at + 2, 2));
                append_range(wide, low == EMPTY_LOW ? ZRange{} : ZRange{float(low), float(high)},
                             F32_PAIRS);
            }
            ranges_ = std::move(wide);
            encoding_ = F32_PAIRS;
        }
        append_range(ranges_, r, encoding_);
        ++cells_;
    }
}

std::vector<uint8_t> ColumnRangesEncoder::finish(const StacksStamp &stamp)
{
    if (cells_ != frame_.cells())
        fail("encode_column_ranges: ", cells_, " ranges for ", frame_.cells(), " cells");
    const std::vector<uint8_t> packed = compressed(ranges_.bytes());
    ranges_ = ByteWriter();
    ByteWriter out;
    out.raw(MAGIC, sizeof MAGIC);
    out.u32(uint32_t(frame_.rows));
    out.u32(uint32_t(frame_.cols));
    out.u32(encoding_);
    out.u64(stamp.end);
    out.u64(stamp.intervals);
    out.u32(stamp.table_crc);
    out.u64(packed.size());
    out.u32(crc32_of(packed.data(), packed.size()));
    out.raw(packed.data(), packed.size());
    return out.bytes();
}

std::vector<uint8_t> encode_column_ranges(const std::vector<ZRange> &ranges, const Frame &frame,
                                          const StacksStamp &stamp)
{
    ColumnRangesEncoder encoder(frame);
    encoder.add(ranges);
    return encoder.finish(stamp);
}

std::optional<std::vector<ZRange>> decode_column_ranges(const uint8_t *data, size_t size,
                                                        const std::string &what,
                                                        const Frame &frame,
                                                        const StacksStamp &stamp,
                                                        unsigned threads)
{
    if (size < HEADER_BYTES || std::memcmp(data, MAGIC, sizeof MAGIC) != 0)
        fail(what, ": not a column ranges member (bad magic number)");
    ByteReader in(data, size, what);
    in.seek(sizeof MAGIC);
    const uint32_t rows = in.u32(), cols = in.u32(), encoding = in.u32();
    StacksStamp made;
    made.end = in.u64();
    made.intervals = in.u64();
    made.table_crc = in.u32();
    const uint64_t packed = in.u64();
    const uint32_t crc = in.u32();
    if (!(made == stamp))
        return std::nullopt; // made from other stacks
    if (rows != uint32_t(frame.rows) || cols != uint32_t(frame.cols) || encoding > F32_PAIRS ||
        packed != size - HEADER_BYTES)
        fail(what, ": its grid or size does not match the stacks (corrupt file)");
    if (crc32_of(data + HEADER_BYTES, packed) != crc)
        fail(what, ": checksum mismatch (corrupt file)");
    const size_t pair = encoding == U16_PAIRS ? 4 : 8;
    std::vector<uint8_t> raw(frame.cells() * pair);
    const size_t n = ZSTD_decompress(raw.data(), raw.size(), data + HEADER_BYTES, packed);
    if (ZSTD_isError(n) || n != raw.size())
        fail(what, ": ", ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size",
             " (corrupt file)");
    std::vector<ZRange> ranges(frame.cells());
    const float depths = float(frame.depths);
    const size_t row_cells = size_t(frame.cols);
    // row by row on all cores (7.4 million columns in a national model,
    // read on every opening)
    for_each_row_in_runs(0, frame.rows, threads, 64, [&](int row) {
        const uint8_t *p = raw.data() + size_t(row) * row_cells * pair;
        ZRange *out = ranges.data() + size_t(row) * row_cells;
        for (size_t c = 0; c < row_cells; ++c, p += pair) {
            ZRange r;
            if (encoding == U16_PAIRS) {
                const uint16_t low = uint16_t(p[0] | p[1] << 8), high = uint16_t(p[2] | p[3] << 8);
                if (low != EMPTY_LOW)
                    r = ZRange{float(low), float(high)};
            }
            else {
                std::memcpy(&r.low, p, 4);
                std::memcpy(&r.high, p + 4, 4);
            }
            // empty as 1 > 0, or a range within the depths
            const bool empty = r.low == 1 && r.high == 0;
            if (!empty && !(r.low >= 0 && r.low < r.high && r.high <= depths))
                fail(what, ": a column range outside the model's depths (corrupt file)");
            out[c] = empty ? ZRange{} : r;
        }
    });
    return ranges;
}

} // namespace sbrt
