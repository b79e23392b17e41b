/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The `tops` member of an SBRT
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/column_tops_file.hpp"

#include <cstring>

#include "util/error.hpp"

namespace sbrt {

namespace {

/// Record `cell` of `raw` (checked against its column's range `range`) as
/// a Record; throws sbrt::Error naming `what` where it is not sound.
template <typename Record>
Record read_top(const uint8_t *raw, uint32_t encoding, const ZRange &range, size_t materials,
                const std::string &what)
{
    Interval top;
    if (encoding == NARROW_RECORDS)
        top = ColumnTopCodec::narrow(raw);
    else {
        std::memcpy(&top.material, raw, 4);
        std::memcpy(&top.top, raw + 4, 4);
    }
    // an empty column where its range is empty; else a drawn material whose
    // bottom lies within the column's range (0 only as its one interval)
    const bool sound = top.material == EMPTY
                           ? range.empty() && top.top == 0
                           : !range.empty() && top.material < materials &&
                                 top.top >= range.low && top.top < range.high &&
                                 (top.top > 0 || range.low == 0);
    if (!sound)
        fail(what, ": a column's top interval outside its range (corrupt file)");
    if constexpr (std::is_same_v<Record, CompactInterval>)
        return {uint16_t(top.material), uint16_t(top.top)};
    else
        return top;
}

/// Each column's top interval of member bytes as `Records`, checked
/// against `ranges`; nothing where stale.
template <typename Records>
std::optional<Records> read_tops(const uint8_t *data, size_t size, const std::string &what,
                                 const Frame &frame, const StacksStamp &stamp,
                                 const ColumnRangeArray &ranges, size_t materials,
                                 unsigned threads)
{
    using Record = typename Records::value_type;
    Records tops(frame.cells());
    const size_t row_cells = size_t(frame.cols);
    const auto read = [&](uint32_t encoding, int first_row, int rows, const uint8_t *p) {
        const size_t first = size_t(first_row) * row_cells;
        const size_t record = column_record_bytes(encoding);
        ranges.visit([&](const auto *range) {
            for (size_t c = first; c < first + size_t(rows) * row_cells; ++c, p += record)
                tops[c] = read_top<Record>(p, encoding, widened(range[c]), materials, what);
        });
    };
    if (!decode_column_member(data, size, what, "column tops", ColumnTopCodec::MAGIC, frame, stamp,
                              column_record_bytes, threads, read))
        return std::nullopt; // made from other stacks
    return tops;
}

/// The encoding a `tops` member's header names.
uint32_t tops_encoding(const uint8_t *data, size_t size, const std::string &what)
{
    return column_member_encoding(data, size, what, "column tops", ColumnTopCodec::MAGIC);
}

} // namespace

void ColumnTopCodec::append(ByteWriter &out, const Interval &top, uint32_t encoding)
{
    if (encoding == NARROW_RECORDS) {
        out.u16(uint16_t(top.material));
        out.u16(uint16_t(top.top));
    }
    else {
        out.u32(top.material);
        out.f32(top.top);
    }
}

Interval ColumnTopCodec::narrow(const uint8_t *record)
{
    return {uint32_t(load_le(record, 2)), float(load_le(record + 2, 2))};
}

uint64_t column_tops_bytes(const uint8_t *data, size_t size, const Frame &frame,
                           const std::string &what)
{
    return frame.cells() * column_record_bytes(tops_encoding(data, size, what));
}

std::optional<IntervalArray> decode_column_tops(const uint8_t *data, size_t size,
                                                const std::string &what, const Frame &frame,
                                                const StacksStamp &stamp,
                                                const ColumnRangeArray &ranges,
                                                size_t materials, unsigned threads)
{
    if (ranges.size() != frame.cells())
        fail(what, ": read without its columns' ranges");
    // held as the member holds them: compact where it is
    if (tops_encoding(data, size, what) == NARROW_RECORDS) {
        if (auto tops = read_tops<CompactIntervals>(data, size, what, frame, stamp, ranges,
                                                    materials, threads))
            return IntervalArray(std::move(*tops));
        return std::nullopt;
    }
    if (auto tops =
            read_tops<Intervals>(data, size, what, frame, stamp, ranges, materials, threads))
        return IntervalArray(std::move(*tops));
    return std::nullopt;
}

} // namespace sbrt
