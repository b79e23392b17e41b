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

namespace sbrt {

namespace {

constexpr char MAGIC[8] = {'S', 'B', 'R', 'T', 'R', 'N', 'G', '1'};
constexpr uint32_t U16_PAIRS = 0, F32_PAIRS = 1;
constexpr uint16_t EMPTY_LOW = 0xffff;

/// Whether a range fits a u16 pair exactly (voxel boundaries).
bool fits_u16(const ZRange &r)
{
    return r.empty() || (r.low >= 0 && r.high < float(EMPTY_LOW) &&
                         float(uint16_t(r.low)) == r.low && float(uint16_t(r.high)) == r.high);
}

void append_range(ByteWriter &raw, const ZRange &r, uint32_t encoding)
{
    if (encoding == U16_PAIRS) {
        raw.u16(r.empty() ? EMPTY_LOW : uint16_t(r.low));
        raw.u16(r.empty() ? 0 : uint16_t(r.high));
    }
    else {
        raw.f32(r.empty() ? 1.0f : r.low);
        raw.f32(r.empty() ? 0.0f : r.high);
    }
}

/// Bytes of a range in `encoding` (0: not one of them).
size_t range_bytes(uint32_t encoding)
{
    return encoding == U16_PAIRS ? 4 : encoding == F32_PAIRS ? 8 : 0;
}

} // namespace

ColumnRangesEncoder::ColumnRangesEncoder(const Frame &frame) : frame_(frame)
{
    ranges_.reserve(size_t(frame.cells()) * 4); // u16 pairs, as voxel models take
}

void ColumnRangesEncoder::add(const std::vector<ZRange> &ranges)
{
    if (cells_ + ranges.size() > frame_.cells())
        fail("encode_column_ranges: more ranges than the frame's ", frame_.cells(), " cells");
    for (const ZRange &r : ranges) {
        if (encoding_ == U16_PAIRS && !fits_u16(r)) {
            // the rest, and those before, as f32 pairs
            ByteWriter wide;
            for (size_t at = 0; at < ranges_.size(); at += 4) {
                const uint16_t low = uint16_t(load_le(ranges_.bytes().data() + at, 2));
                const uint16_t high = uint16_t(load_le(ranges_.bytes().data() + at + 2, 2));
                append_range(wide, low == EMPTY_LOW ? ZRange{} : ZRange{float(low), float(high)},
                             F32_PAIRS);
            }
            ranges_ = std::move(wide);
            encoding_ = F32_PAIRS;
        }
        append_range(ranges_, r, encoding_);
        ++cells_;
    }
}

std::vector<uint8_t> ColumnRangesEncoder::finish(const StacksStamp &stamp)
{
    if (cells_ != frame_.cells())
        fail("encode_column_ranges: ", cells_, " ranges for ", frame_.cells(), " cells");
    std::vector<uint8_t> out =
        encode_column_member(MAGIC, frame_, encoding_, ranges_.bytes(), stamp);
    ranges_ = ByteWriter();
    return out;
}

std::vector<uint8_t> encode_column_ranges(const std::vector<ZRange> &ranges, const Frame &frame,
                                          const StacksStamp &stamp)
{
    ColumnRangesEncoder encoder(frame);
    encoder.add(ranges);
    return encoder.finish(stamp);
}

std::optional<std::vector<ZRange>> decode_column_ranges(const uint8_t *data, size_t size,
                                                        const std::string &what,
                                                        const Frame &frame,
                                                        const StacksStamp &stamp,
                                                        unsigned threads)
{
    std::vector<ZRange> ranges(frame.cells());
    const float depths = float(frame.depths);
    const size_t row_cells = size_t(frame.cols);
    // band by band on all cores (7.4 million columns in a national model,
    // read on every opening)
    const auto read = [&](uint32_t encoding, int first_row, int rows, const uint8_t *p) {
        ZRange *out = ranges.data() + size_t(first_row) * row_cells;
        const size_t pair = range_bytes(encoding);
        for (size_t c = 0; c < size_t(rows) * row_cells; ++c, p += pair) {
            ZRange r;
            if (encoding == U16_PAIRS) {
                const uint16_t low = uint16_t(p[0] | p[1] << 8), high = uint16_t(p[2] | p[3] << 8);
                if (low != EMPTY_LOW)
                    r = ZRange{float(low), float(high)};
            }
            else {
                std::memcpy(&r.low, p, 4);
                std::memcpy(&r.high, p + 4, 4);
            }
            // empty as 1 > 0, or a range within the depths
            const bool empty = r.low == 1 && r.high == 0;
            if (!empty && !(r.low >= 0 && r.low < r.high && r.high <= depths))
                fail(what, ": a column range outside the model's depths (corrupt file)");
            out[c] = empty ? ZRange{} : r;
        }
    };
    if (!decode_column_member(data, size, what, "column ranges", MAGIC, frame, stamp,
                              range_bytes, threads, read))
        return std::nullopt; // made from other stacks
    return ranges;
}

} // namespace sbrt
