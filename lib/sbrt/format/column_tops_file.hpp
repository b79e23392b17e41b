/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `tops` member of an SBRT: each column's top interval,
 *            stored beside a format 2.1 `stacks` file so that a ray that
 *            meets only the top of a column needs no block (issue 49: a
 *            national model's default view decodes a tenth of the blocks
 *            it touches)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_TOPS_FILE_HPP
#define SBRT_COLUMN_TOPS_FILE_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "format/byte_io.hpp"
#include "format/column_member.hpp"
#include "model/column_range_array.hpp"
#include "model/interval_array.hpp"
#include "model/z_range.hpp"

namespace sbrt {

/// \brief How the `tops` member stores a column's top interval as
/// column_tops() gives it (encode_column_member: magic "SBRTTOP1";
/// narrow: u16 material, u16 bottom; wide: u32 material, f32 bottom).
struct ColumnTopCodec {
    using Value = Interval;
    static constexpr char MAGIC[8] = {'S', 'B', 'R', 'T', 'T', 'O', 'P', '1'};
    static constexpr const char *NAME = "ColumnTopsEncoder";
    static bool fits_narrow(const Interval &top) { return fits_compact(top); }
    static void append(ByteWriter &out, const Interval &top, uint32_t encoding);
    static Interval narrow(const uint8_t *record);
};

/// The `tops` member, band by band of rows (4 bytes a column of a voxel
/// model).
using ColumnTopsEncoder = ColumnMemberEncoder<ColumnTopCodec>;

/// Bytes the top intervals of untrusted member bytes take in memory for
/// `frame`, read from its header alone; throws sbrt::Error naming `what`
/// where it is not a `tops` member this reader knows.
uint64_t column_tops_bytes(const uint8_t *data, size_t size, const Frame &frame,
                           const std::string &what);

/// Each column's top interval from untrusted member bytes for stacks of
/// `frame` stamped `stamp`, whose columns' ranges are `ranges` and whose
/// materials number `materials`: a record a cell (material, and its bottom
/// in `top`), compact where the member is. Nothing where the member was
/// made from other stacks (stale). Damage, or a record its column's range
/// contradicts, throws sbrt::Error naming `what`.
std::optional<IntervalArray> decode_column_tops(const uint8_t *data, size_t size,
                                                const std::string &what, const Frame &frame,
                                                const StacksStamp &stamp,
                                                const ColumnRangeArray &ranges,
                                                size_t materials, unsigned threads = 0);

} // namespace sbrt

#endif
