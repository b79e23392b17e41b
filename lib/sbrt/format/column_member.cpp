/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The per-column members beside a format 2.1 `stacks` file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/column_member.hpp"

#include <cstring>
#include <memory>

#include <zstd.h>

#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

constexpr size_t HEADER_BYTES = 8 + 3 * 4 + 8 + 8 + 4 + 8 + 4;

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
            fail("encode_column_member: zstd: ", ZSTD_getErrorName(left));
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

std::vector<uint8_t> encode_column_member(const char (&magic)[8], const Frame &frame,
                                          uint32_t encoding, const std::vector<uint8_t> &records,
                                          const StacksStamp &stamp)
{
    const std::vector<uint8_t> packed = compressed(records);
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

std::optional<ColumnRecords> decode_column_member(const uint8_t *data, size_t size,
                                                  const std::string &what, const char *kind,
                                                  const char (&magic)[8], const Frame &frame,
                                                  const StacksStamp &stamp,
                                                  size_t (*record_bytes)(uint32_t encoding))
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
    ColumnRecords out;
    out.encoding = encoding;
    out.bytes.resize(frame.cells() * record);
    const size_t n = ZSTD_decompress(out.bytes.data(), out.bytes.size(), data + HEADER_BYTES,
                                     packed);
    if (ZSTD_isError(n) || n != out.bytes.size())
        fail(what, ": ", ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size",
             " (corrupt file)");
    return out;
}

} // namespace sbrt
