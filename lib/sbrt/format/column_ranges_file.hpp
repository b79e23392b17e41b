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

#include "format/byte_io.hpp"
#include "format/column_member.hpp"
#include "model/column_range_array.hpp"
#include "model/model.hpp"
#include "model/z_range.hpp"

namespace sbrt {

/// \brief How the `ranges` member stores a column's range
/// (encode_column_member: magic "SBRTRNG1"; narrow: u16 low, u16 high, an
/// empty column 0xffff, 0; wide: f32 low, f32 high, an empty column 1,
/// 0).
struct ColumnRangeCodec {
    using Value = ZRange;
    static constexpr char MAGIC[8] = {'S', 'B', 'R', 'T', 'R', 'N', 'G', '1'};
    static constexpr const char *NAME = "encode_column_ranges";
    /// Whether a range fits a u16 pair exactly (voxel boundaries).
    static bool fits_narrow(const ZRange &range);
    static void append(ByteWriter &out, const ZRange &range, uint32_t encoding);
    static ZRange narrow(const uint8_t *record);
};

/// The `ranges` member, band by band of rows (4 bytes a column of a voxel
/// model, 8 where a range is not a pair of voxel boundaries up to 65534).
using ColumnRangesEncoder = ColumnMemberEncoder<ColumnRangeCodec>;

/// The member's bytes for `ranges` (row by row, row 0 north).
std::vector<uint8_t> encode_column_ranges(const std::vector<ZRange> &ranges, const Frame &frame,
                                          const StacksStamp &stamp);

/// The ranges of untrusted member bytes for stacks of `frame` stamped
/// `stamp`, held compact where the member is narrow; nothing where the
/// member was made from other stacks (stale: read the blocks instead).
/// Damage throws sbrt::Error naming `what`. Converted row by row on
/// `threads` threads (0: all cores).
std::optional<ColumnRangeArray> decode_column_ranges(const uint8_t *data, size_t size,
                                                     const std::string &what, const Frame &frame,
                                                     const StacksStamp &stamp,
                                                     unsigned threads = 0);

} // namespace sbrt

#endif
