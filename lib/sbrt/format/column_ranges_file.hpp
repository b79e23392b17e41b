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
#include "model/model.hpp"
#include "model/z_range.hpp"

namespace sbrt {

/// The member's bytes (encode_column_member): magic "SBRTRNG1", encoding
/// 0: u16 low, u16 high, an empty column 0xffff, 0; 1: f32 low, f32 high,
/// an empty column 1, 0.
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
