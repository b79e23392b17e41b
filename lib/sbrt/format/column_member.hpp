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

#include "format/stacks_v2_layout.hpp"

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

/// Converts a band of whole rows of a member's records in `encoding`:
/// rows [first_row, first_row + rows), `record_bytes(encoding)` a column.
using ColumnBandReader =
    std::function<void(uint32_t encoding, int first_row, int rows, const uint8_t *records)>;

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
