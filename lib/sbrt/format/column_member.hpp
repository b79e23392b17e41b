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
#include <optional>
#include <string>
#include <vector>

#include "format/stacks_v2_layout.hpp"
#include "util/unfilled_allocator.hpp"

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

/// The member's bytes: the 8-byte `magic`, u32 rows, u32 cols, u32
/// encoding, the stamp (u64 end, u64 intervals, u32 table crc), u64
/// compressed bytes, u32 their crc32; then `records` (one a column, row
/// by row, row 0 north) zstd-compressed.
std::vector<uint8_t> encode_column_member(const char (&magic)[8], const Frame &frame,
                                          uint32_t encoding, const std::vector<uint8_t> &records,
                                          const StacksStamp &stamp);

/// \brief A member's records, decompressed and checked against its crc.
struct ColumnRecords {
    uint32_t encoding = 0;
    /// every byte written by the decompressor (never zero-filled first)
    std::vector<uint8_t, UnfilledAllocator<uint8_t>> bytes;
};

/// The records of untrusted member bytes for stacks of `frame` stamped
/// `stamp`, `record_bytes(encoding)` bytes a column (0 for an encoding
/// this reader does not know); nothing where the member was made from
/// other stacks (stale). Damage, another magic or an unknown encoding
/// throw sbrt::Error naming `what` (`kind`: what the member holds).
std::optional<ColumnRecords> decode_column_member(const uint8_t *data, size_t size,
                                                  const std::string &what, const char *kind,
                                                  const char (&magic)[8], const Frame &frame,
                                                  const StacksStamp &stamp,
                                                  size_t (*record_bytes)(uint32_t encoding));

} // namespace sbrt

#endif
