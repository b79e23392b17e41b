/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The per-column members beside a format 2.1 `stacks` file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/column_member.hpp"

#include <algorithm>
#include <cstring>
#include <memory>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

namespace {

constexpr size_t HEADER_BYTES = 8 + 3 * 4 + 8 + 8 + 4 + 8 + 4;

using Compressor = std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)>;

/// `raw` zstd-compressed (level 3) as one frame appended to `out`,
/// streamed (`out` grows by what it holds, not by the compression bound).
void append_frame(ZSTD_CCtx *context, const uint8_t *raw, size_t size,
                  std::vector<uint8_t> &out)
{
    ZSTD_CCtx_reset(context, ZSTD_reset_session_only);
    ZSTD_CCtx_setPledgedSrcSize(context, size);
    std::vector<uint8_t> chunk(ZSTD_CStreamOutSize());
    ZSTD_inBuffer in = {raw, size, 0};
    for (;;) {
        ZSTD_outBuffer o = {chunk.data(), chunk.size(), 0};
        const size_t left = ZSTD_compressStream2(context, &o, &in, ZSTD_e_end);
        if (ZSTD_isError(left))
            fail("encode_column_member: zstd: ", ZSTD_getErrorName(left));
        out.insert(out.end(), chunk.begin(), chunk.begin() + ptrdiff_t(o.pos));
        if (left == 0)
            return;
    }
}

/// A frame of a member: where its bytes lie, and the rows it holds.
struct MemberFrame {
    const uint8_t *bytes;
    size_t size;
    int first_row, rows;
};

/// The frames of `packed` (checksummed), each of whole rows of
/// `row_bytes`, together `rows`; throws sbrt::Error naming `what` else.
std::vector<MemberFrame> member_frames(const uint8_t *packed, size_t size, size_t row_bytes,
                                       int rows, const std::string &what)
{
    std::vector<MemberFrame> frames;
    int row = 0;
    for (size_t at = 0; at < size;) {
        const size_t bytes = ZSTD_findFrameCompressedSize(packed + at, size - at);
        const unsigned long long content = ZSTD_isError(bytes)
                                               ? ZSTD_CONTENTSIZE_ERROR
                                               : ZSTD_getFrameContentSize(packed + at, bytes);
        if (content == ZSTD_CONTENTSIZE_ERROR || content == ZSTD_CONTENTSIZE_UNKNOWN ||
            content % row_bytes != 0 || content / row_bytes > uint64_t(rows - row))
            fail(what, ": its frames do not hold whole rows of the grid (corrupt file)");
        frames.push_back({packed + at, bytes, row, int(content / row_bytes)});
        row += int(content / row_bytes);
        at += bytes;
    }
    if (row != rows)
        fail(what, ": its frames hold ", row, " of the grid's ", rows, " rows (corrupt file)");
    return frames;
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

std::vector<uint8_t> encode_column_member(const char (&magic)[8], const Frame &frame,
                                          uint32_t encoding, const std::vector<uint8_t> &records,
                                          const StacksStamp &stamp)
{
    const Compressor context(ZSTD_createCCtx(), ZSTD_freeCCtx);
    ZSTD_CCtx_setParameter(context.get(), ZSTD_c_compressionLevel, 3);
    std::vector<uint8_t> packed;
    const size_t band = size_t(COLUMN_MEMBER_FRAME_ROWS) * size_t(frame.cols) *
                        (frame.cells() ? records.size() / frame.cells() : 0);
    for (size_t at = 0; at < records.size() || packed.empty(); at += band)
        append_frame(context.get(), records.data() + at, std::min(band, records.size() - at),
                     packed);
    ByteWriter out;
    out.raw(magic, sizeof magic);
    out.u32(uint32_t(frame.rows));
    out.u32(uint32_t(frame.cols));
    out.u32(encoding);
    out.u64(stamp.end);
    out.u64(stamp.intervals);
    out.u32(stamp.table_crc);
    out.u64(packed.size());
    out.u32(crc32_of(packed.data(), packed.size()));
    out.raw(packed.data(), packed.size());
    return out.bytes();
}

uint32_t column_member_encoding(const uint8_t *data, size_t size, const std::string &what,
                                const char *kind, const char (&magic)[8])
{
    constexpr size_t ENCODING_AT = sizeof magic + 2 * 4;
    if (size < ENCODING_AT + 4 || std::memcmp(data, magic, sizeof magic) != 0)
        fail(what, ": not a ", kind, " member (bad magic number)");
    const uint32_t encoding = uint32_t(load_le(data + ENCODING_AT, 4));
    if (column_record_bytes(encoding) == 0)
        fail(what, ": an encoding this reader does not know (corrupt file)");
    return encoding;
}

std::optional<uint32_t> decode_column_member(const uint8_t *data, size_t size,
                                             const std::string &what, const char *kind,
                                             const char (&magic)[8], const Frame &frame,
                                             const StacksStamp &stamp,
                                             size_t (*record_bytes)(uint32_t encoding),
                                             unsigned threads, const ColumnBandReader &read)
{
    if (size < HEADER_BYTES || std::memcmp(data, magic, sizeof magic) != 0)
        fail(what, ": not a ", kind, " member (bad magic number)");
    ByteReader in(data, size, what);
    in.seek(sizeof magic);
    const uint32_t rows = in.u32(), cols = in.u32(), encoding = in.u32();
    StacksStamp made;
    made.end = in.u64();
    made.intervals = in.u64();
    made.table_crc = in.u32();
    const uint64_t packed = in.u64();
    const uint32_t crc = in.u32();
    if (!(made == stamp))
        return std::nullopt; // made from other stacks
    const size_t record = record_bytes(encoding);
    if (rows != uint32_t(frame.rows) || cols != uint32_t(frame.cols) || record == 0 ||
        packed != size - HEADER_BYTES)
        fail(what, ": its grid or size does not match the stacks (corrupt file)");
    if (crc32_of(data + HEADER_BYTES, packed) != crc)
        fail(what, ": checksum mismatch (corrupt file)");
    const size_t row_bytes = size_t(frame.cols) * record;
    const std::vector<MemberFrame> frames =
        member_frames(data + HEADER_BYTES, packed, row_bytes, frame.rows, what);
    for_each_row(int(frames.size()), threads, [&](int f) {
        const MemberFrame &band = frames[size_t(f)];
        std::vector<uint8_t, UnfilledAllocator<uint8_t>> raw(size_t(band.rows) * row_bytes);
        const size_t n = ZSTD_decompress(raw.data(), raw.size(), band.bytes, band.size);
        if (ZSTD_isError(n) || n != raw.size())
            fail(what, ": ", ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size",
                 " (corrupt file)");
        read(encoding, band.first_row, band.rows, raw.data());
    });
    return encoding;
}

} // namespace sbrt
