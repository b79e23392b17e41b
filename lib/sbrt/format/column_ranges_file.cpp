/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `ranges` member of an SBRT
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/column_ranges_file.hpp"

#include <cstring>

#include "format/byte_io.hpp"
#include "format/stacks_fields.hpp"
#include "format/stacks_v2_layout.hpp"
#include "util/error.hpp"
#include "util/unfilled_allocator.hpp"

namespace sbrt {

namespace {

constexpr uint16_t EMPTY_LOW = 0xffff;

} // namespace

bool ColumnRangeCodec::fits_narrow(const ZRange &r)
{
    // a CompactRange's, less the high that marks an empty column here
    return fits_compact_range(r) && (r.empty() || r.high < float(EMPTY_LOW));
}

void ColumnRangeCodec::append(ByteWriter &out, const ZRange &r, uint32_t encoding)
{
    if (encoding == NARROW_RECORDS) {
        out.u16(r.empty() ? EMPTY_LOW : uint16_t(r.low));
        out.u16(r.empty() ? 0 : uint16_t(r.high));
    }
    else {
        out.f32(r.empty() ? 1.0f : r.low);
        out.f32(r.empty() ? 0.0f : r.high);
    }
}

ZRange ColumnRangeCodec::narrow(const uint8_t *record)
{
    const uint16_t low = uint16_t(load_le(record, 2)), high = uint16_t(load_le(record + 2, 2));
    return low == EMPTY_LOW ? ZRange{} : ZRange{float(low), float(high)};
}

std::vector<uint8_t> encode_column_ranges(const std::vector<ZRange> &ranges, const Frame &frame,
                                          const StacksStamp &stamp)
{
    ColumnRangesEncoder encoder(frame);
    encoder.add(ranges);
    return encoder.finish(stamp);
}

namespace {

/// A member's column range, checked: empty as 1 > 0 (ZRange{}), or a
/// range within the depths; throws sbrt::Error naming `what` else.
ZRange checked_range(const ZRange &r, float depths, const std::string &what)
{
    if (r.low == 1 && r.high == 0)
        return ZRange{};
    if (!(r.low >= 0 && r.low < r.high && r.high <= depths))
        fail(what, ": a column range outside the model's depths (corrupt file)");
    return r;
}

} // namespace

std::optional<ColumnRangeArray> decode_column_ranges(const uint8_t *data, size_t size,
                                                     const std::string &what,
                                                     const Frame &frame,
                                                     const StacksStamp &stamp,
                                                     unsigned threads)
{
    const uint32_t encoding =
        column_member_encoding(data, size, what, "column ranges", ColumnRangeCodec::MAGIC);
    const float depths = float(frame.depths);
    const size_t row_cells = size_t(frame.cols);
    // band by band on all cores (7.4 million columns in a national model,
    // read on every opening), held as the member holds them: a narrow
    // member's u16 pairs as they are (30 MB in a national model, and the
    // tracer's level 0), a wide one's floats
    if (encoding == NARROW_RECORDS) {
        CompactRanges ranges(frame.cells()); // every column written below
        const auto read = [&](uint32_t, int first_row, int rows, const uint8_t *p) {
            CompactRange *out = ranges.data() + size_t(first_row) * row_cells;
            for (size_t c = 0; c < size_t(rows) * row_cells; ++c, p += 4) {
                const ZRange r = checked_range(ColumnRangeCodec::narrow(p), depths, what);
                out[c] = r.empty() ? CompactRange{}
                                   : CompactRange{uint16_t(r.low), uint16_t(r.high)};
            }
        };
        if (!decode_column_member(data, size, what, "column ranges", ColumnRangeCodec::MAGIC,
                                  frame, stamp, column_record_bytes, threads, read))
            return std::nullopt; // made from other stacks
        return ColumnRangeArray(std::move(ranges));
    }
    std::vector<ZRange> ranges = vector_on_huge_pages<ZRange>(frame.cells());
    const auto read = [&](uint32_t, int first_row, int rows, const uint8_t *p) {
        ZRange *out = ranges.data() + size_t(first_row) * row_cells;
        for (size_t c = 0; c < size_t(rows) * row_cells; ++c, p += 8) {
            ZRange r;
            std::memcpy(&r.low, p, 4);
            std::memcpy(&r.high, p + 4, 4);
            out[c] = checked_range(r, depths, what);
        }
    };
    if (!decode_column_member(data, size, what, "column ranges", ColumnRangeCodec::MAGIC, frame,
                              stamp, column_record_bytes, threads, read))
        return std::nullopt; // made from other stacks
    return ColumnRangeArray(std::move(ranges));
}

} // namespace sbrt
