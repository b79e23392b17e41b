/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What the per-column members beside a format 2.1 `stacks`
 *            file share (`ranges`, `tops`): a header naming the grid, the
 *            encoding and the stacks they were made from, then one
 *            zstd-compressed record a column
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_MEMBER_HPP
#define SBRT_COLUMN_MEMBER_HPP

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "format/byte_io.hpp"
#include "format/stacks_v2_layout.hpp"
#include "util/error.hpp"

namespace sbrt {

/// \brief The stacks file a per-column member was made from: its header's
/// end, block table checksum and interval count (a `stacks` written again
/// without its members no longer matches).
struct StacksStamp {
    uint64_t end = 0, intervals = 0;
    uint32_t table_crc = 0;
    bool operator==(const StacksStamp &other) const
    {
        return end == other.end && intervals == other.intervals &&
               table_crc == other.table_crc;
    }
};

/// The stamp of a format 2 stacks file's header (as open_stacks_v2 read
/// and checked it).
StacksStamp stamp_of(const HeaderV2 &header);
/// The stamp of untrusted format 2 stacks bytes (the header read and
/// checked; throws sbrt::Error naming `what`).
StacksStamp stacks_stamp(const uint8_t *data, size_t size, const std::string &what);

/// Rows of records a zstd frame of a member holds (its last frame: the
/// rest): frames are decompressed in parallel, each into a buffer of its
/// own, so that no buffer of the whole member is made.
constexpr int COLUMN_MEMBER_FRAME_ROWS = 64;

/// The member's bytes: the 8-byte `magic`, u32 rows, u32 cols, u32
/// encoding, the stamp (u64 end, u64 intervals, u32 table crc), u64
/// compressed bytes, u32 their crc32; then `records` (one a column, row
/// by row, row 0 north) zstd-compressed, a frame every
/// COLUMN_MEMBER_FRAME_ROWS rows (members written before held one frame;
/// both are one zstd stream).
std::vector<uint8_t> encode_column_member(const char (&magic)[8], const Frame &frame,
                                          uint32_t encoding, const std::vector<uint8_t> &records,
                                          const StacksStamp &stamp);

/// Encodings of a per-column member's records: two 16-bit values a
/// column while every record fits them, else 8 bytes a column (wide).
constexpr uint32_t NARROW_RECORDS = 0, WIDE_RECORDS = 1;
/// Bytes of a record in `encoding` (0: not one of them).
inline size_t column_record_bytes(uint32_t encoding)
{
    return encoding == NARROW_RECORDS ? 4 : encoding == WIDE_RECORDS ? 8 : 0;
}

/// \brief A per-column member's bytes, band by band of rows: its records
/// held packed as the member stores them, narrow until a value does not
/// fit them (then those before are widened too). `Codec` names the
/// member (`MAGIC`, `NAME` in errors) and its `Value`, says whether one
/// `fits_narrow`, writes it in an encoding (`append`) and reads a narrow
/// record back (`narrow`).
template <typename Codec>
class ColumnMemberEncoder {
public:
    using Value = typename Codec::Value;

    explicit ColumnMemberEncoder(const Frame &frame) : frame_(frame)
    {
        // narrow, as voxel models take
        records_.reserve(size_t(frame.cells()) * column_record_bytes(NARROW_RECORDS));
    }
    /// The values of the next columns (row by row, row 0 north).
    void add(const std::vector<Value> &values)
    {
        if (cells_ + values.size() > frame_.cells())
            fail(Codec::NAME, ": more columns than the frame's ", frame_.cells(), " cells");
        for (const Value &value : values) {
            if (encoding_ == NARROW_RECORDS && !Codec::fits_narrow(value)) {
                ByteWriter wide;
                for (size_t at = 0; at < records_.size();
                     at += column_record_bytes(NARROW_RECORDS))
                    Codec::append(wide, Codec::narrow(records_.bytes().data() + at),
                                  WIDE_RECORDS);
                records_ = std::move(wide);
                encoding_ = WIDE_RECORDS;
            }
            Codec::append(records_, value, encoding_);
            ++cells_;
        }
    }
    /// The member's bytes, once every column's value was added; throws
    /// sbrt::Error else.
    std::vector<uint8_t> finish(const StacksStamp &stamp)
    {
        if (cells_ != frame_.cells())
            fail(Codec::NAME, ": ", cells_, " columns for ", frame_.cells(), " cells");
        std::vector<uint8_t> out =
            encode_column_member(Codec::MAGIC, frame_, encoding_, records_.bytes(), stamp);
        records_ = ByteWriter();
        return out;
    }

private:
    Frame frame_;
    uint32_t encoding_ = NARROW_RECORDS;
    ByteWriter records_;
    uint64_t cells_ = 0;
};

/// Converts a band of whole rows of a member's records in `encoding`:
/// rows [first_row, first_row + rows), `record_bytes(encoding)` a column.
using ColumnBandReader =
    std::function<void(uint32_t encoding, int first_row, int rows, const uint8_t *records)>;

/// The encoding a per-column member's header names (NARROW_RECORDS or
/// WIDE_RECORDS); throws sbrt::Error naming `what` where the bytes are not
/// such a member (another `magic`; `kind`: what it holds) or name an
/// encoding this reader does not know.
uint32_t column_member_encoding(const uint8_t *data, size_t size, const std::string &what,
                                const char *kind, const char (&magic)[8]);

/// The encoding of untrusted member bytes for stacks of `frame` stamped
/// `stamp`, whose records (`record_bytes(encoding)` bytes a column; 0 for
/// an encoding this reader does not know) are handed to `read` band by
/// band (a frame each, on `threads` threads; 0: all cores); nothing where
/// the member was made from other stacks (stale). Damage, another magic
/// or an unknown encoding throw sbrt::Error naming `what` (`kind`: what
/// the member holds), as `read` may.
std::optional<uint32_t> decode_column_member(const uint8_t *data, size_t size,
                                             const std::string &what, const char *kind,
                                             const char (&magic)[8], const Frame &frame,
                                             const StacksStamp &stamp,
                                             size_t (*record_bytes)(uint32_t encoding),
                                             unsigned threads, const ColumnBandReader &read);

} // namespace sbrt

#endif
