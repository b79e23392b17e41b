/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `ranges` member of an SBRT: each column's range of
 *            material, stored beside a format 2.1 `stacks` file so that a
 *            paged model opens without decoding a block (issue 49)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_RANGES_FILE_HPP
#define SBRT_COLUMN_RANGES_FILE_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "format/stacks_v2_layout.hpp"
#include "format/byte_io.hpp"
#include "model/model.hpp"
#include "model/z_range.hpp"

namespace sbrt {

/// \brief The stacks file a `ranges` member was made from: its header's
/// end, block table checksum and interval count (a `stacks` written again
/// without its ranges no longer matches).
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

/// The member's bytes: magic "SBRTRNG1", u32 rows, u32 cols, u32 encoding
/// (0: u16 low, u16 high, an empty column 0xffff, 0; 1: f32 low, f32
/// high, an empty column 1, 0), the stamp (u64 end, u64 intervals, u32
/// table crc), u64 compressed bytes, u32 their crc32; then the ranges,
/// row by row (row 0 north), zstd-compressed.
std::vector<uint8_t> encode_column_ranges(const std::vector<ZRange> &ranges, const Frame &frame,
                                          const StacksStamp &stamp);

/// \brief encode_column_ranges band by band of rows: the ranges held
/// packed as the member stores them (4 bytes a column of a voxel model,
/// 8 where a range is not a pair of voxel boundaries up to 65534), not
/// as ZRange.
class ColumnRangesEncoder {
public:
    explicit ColumnRangesEncoder(const Frame &frame);
    /// The ranges of the next columns (row by row, row 0 north).
    void add(const std::vector<ZRange> &ranges);
    /// The member's bytes, once every column's range was added; throws
    /// sbrt::Error else.
    std::vector<uint8_t> finish(const StacksStamp &stamp);

private:
    Frame frame_;
    uint32_t encoding_ = 0; ///< u16 pairs until a range does not fit them
    ByteWriter ranges_;
    uint64_t cells_ = 0;
};

/// The ranges of untrusted member bytes for stacks of `frame` stamped
/// `stamp`; nothing where the member was made from other stacks (stale:
/// read the blocks instead). Damage throws sbrt::Error naming `what`.
/// Converted row by row on `threads` threads (0: all cores).
std::optional<std::vector<ZRange>> decode_column_ranges(const uint8_t *data, size_t size,
                                                        const std::string &what,
                                                        const Frame &frame,
                                                        const StacksStamp &stamp,
                                                        unsigned threads = 0);

} // namespace sbrt

#endif
