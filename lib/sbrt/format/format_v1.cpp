/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Format v1 of the `stacks` file (8 bytes an interval, no
 *            compression): still read, and written where a test needs the
 *            model's bytes as they are
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/format_v1.hpp"

#include <cstddef>
#include <cstring>

#include "format/byte_io.hpp"
#include "util/error.hpp"
#include "format/stacks_fields.hpp"

namespace sbrt {

namespace {

constexpr size_t INTERVAL_BYTES = 8;

struct Offsets {
    uint64_t materials, counts, intervals, end;
};

Offsets layout(uint64_t materials, uint64_t cells, uint64_t intervals)
{
    Offsets o;
    o.materials = STACKS_V1_HEADER_SIZE;
    o.counts = o.materials + materials * MATERIAL_RECORD_BYTES;
    o.intervals = o.counts + cells * 4;
    o.end = o.intervals + intervals * INTERVAL_BYTES;
    return o;
}

} // namespace

std::vector<uint8_t> encode_stacks_v1(const Model &model)
{
    const Frame &f = model.frame();
    const auto &materials = model.materials();
    const auto &intervals = model.intervals();
    const Offsets o = layout(materials.size(), f.cells(), intervals.size());

    // the body after room for the header, written in place: one buffer
    ByteWriter body;
    body.reserve(STACKS_V1_HEADER_SIZE + materials.size() * 8 + f.cells() * 4 +
                 intervals.size() * sizeof(Interval));
    body.raw(std::vector<uint8_t>(STACKS_V1_HEADER_SIZE).data(), STACKS_V1_HEADER_SIZE);
    write_materials(body, materials);
    const size_t counts_at = body.size();
    for (uint64_t c = 0; c < f.cells(); ++c)
        body.u32(model.stack_size(c));
    const size_t intervals_at = body.size();
    if (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ && !intervals.is_compact()) {
        // the file's record is the host's (load_intervals reads it so too)
        body.raw(intervals.wide_data(), intervals.size() * sizeof(Interval));
    }
    else {
        for (size_t i = 0; i < intervals.size(); ++i) {
            body.u32(intervals[i].material);
            body.f32(intervals[i].top);
        }
    }
    const uint8_t *b = body.bytes().data();

    ByteWriter head;
    head.raw(STACKS_MAGIC, sizeof STACKS_MAGIC);
    head.u32(FORMAT_V1_VERSION);
    head.u32(STACKS_V1_HEADER_SIZE);
    write_frame(head, f);
    head.u32(uint32_t(materials.size()));
    head.u64(intervals.size());
    head.u64(o.materials);
    head.u64(o.counts);
    head.u64(o.intervals);
    const size_t start = STACKS_V1_HEADER_SIZE;
    head.u32(crc32_of(b + start, counts_at - start));
    head.u32(crc32_of(b + counts_at, intervals_at - counts_at));
    head.u32(crc32_of(b + intervals_at, body.size() - intervals_at));
    head.u32(crc32_of(head.bytes().data(), head.size()));
    SBRT_CHECK_EQ(head.size(), size_t(STACKS_V1_HEADER_SIZE), "encode_stacks");

    std::copy(head.bytes().begin(), head.bytes().end(), body.bytes().begin());
    return std::move(body.bytes());
}

namespace {

/// Intervals as stored: u32 material, f32 top, little-endian, 8 bytes
/// each; a view of them where `keep` holds them and the host reads them as
/// they are.
IntervalArray load_intervals(const uint8_t *p, size_t count,
                             std::shared_ptr<const void> keep)
{
    static_assert(sizeof(Interval) == 8 && offsetof(Interval, top) == 4,
                  "Interval is the file's record");
    constexpr bool native = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
    if (native && keep && reinterpret_cast<uintptr_t>(p) % alignof(Interval) == 0)
        return IntervalArray(std::move(keep), reinterpret_cast<const Interval *>(p), count);
    Intervals intervals(count);
    if (native) {
        if (count)
            std::memcpy(intervals.data(), p, count * sizeof(Interval));
        return intervals;
    }
    for (Interval &iv : intervals) {
        iv.material = uint32_t(load_le(p, 4));
        const uint32_t bits = uint32_t(load_le(p + 4, 4));
        std::memcpy(&iv.top, &bits, 4);
        p += 8;
    }
    return intervals;
}

} // namespace

Model decode_stacks_v1(const uint8_t *data, size_t size, const std::string &what,
                    std::shared_ptr<const void> keep)
{
    ByteReader in(data, size, what);
    if (size < sizeof STACKS_MAGIC || std::memcmp(data, STACKS_MAGIC, sizeof STACKS_MAGIC) != 0)
        fail(what, ": not an SBRT stacks file (bad magic number)");
    in.seek(sizeof STACKS_MAGIC);
    const uint32_t version = in.u32();
    if (version != FORMAT_V1_VERSION)
        fail(what, ": format version ", version, " is not supported (this "
             "build reads version ", FORMAT_V1_VERSION, ")");
    const uint32_t header_size = in.u32();
    if (header_size != STACKS_V1_HEADER_SIZE)
        fail(what, ": header size ", header_size, ", expected ",
             STACKS_V1_HEADER_SIZE);
    if (size < STACKS_V1_HEADER_SIZE)
        fail(what, ": truncated header (", size, " of ", STACKS_V1_HEADER_SIZE,
             " bytes)");
    if (crc32_of(data, STACKS_V1_HEADER_SIZE - 4) !=
        ByteReader(data + STACKS_V1_HEADER_SIZE - 4, 4, what).u32())
        fail(what, ": header checksum mismatch (corrupt file)");

    const Frame f = read_frame(in, what);
    const uint32_t material_count = in.u32();
    const uint64_t interval_count = in.u64();
    if (material_count == 0 || material_count > MAX_MATERIALS)
        fail(what, ": material count ", material_count, " not in 1..",
             MAX_MATERIALS);
    if (interval_count > UINT32_MAX)
        fail(what, ": interval count ", interval_count, " exceeds 2^32-1");
    const Offsets expected = layout(material_count, f.cells(), interval_count);
    const uint64_t at_materials = in.u64(), at_counts = in.u64(),
                   at_intervals = in.u64();
    if (at_materials != expected.materials || at_counts != expected.counts ||
        at_intervals != expected.intervals)
        fail(what, ": section offsets do not match the counts (corrupt file)");
    if (expected.end != size)
        fail(what, ": file has ", size, " bytes, its header describes ",
             expected.end, expected.end > size ? " (truncated)" : "");
    const uint32_t crc_materials = in.u32(), crc_counts = in.u32(),
                   crc_intervals = in.u32();
    if (crc32_of(data + at_materials, at_counts - at_materials) !=
            crc_materials ||
        crc32_of(data + at_counts, at_intervals - at_counts) != crc_counts ||
        crc32_of(data + at_intervals, expected.end - at_intervals) !=
            crc_intervals)
        fail(what, ": data checksum mismatch (corrupt file)");

    // sections: materials, per-cell counts, intervals
    in.seek(at_materials);
    std::vector<Material> materials = read_materials(in, material_count);
    // the sections' sizes were checked against the file above: read them
    // straight from memory (little-endian, as the file is)
    std::vector<uint32_t> offsets(f.cells() + 1, 0);
    uint64_t total = 0;
    const uint8_t *counts = data + at_counts;
    for (uint64_t c = 0; c < f.cells(); ++c) {
        total += load_le(counts + 4 * c, 4);
        if (total > interval_count)
            fail(what, ": stack sizes exceed the interval count");
        offsets[c + 1] = uint32_t(total);
    }
    if (total != interval_count)
        fail(what, ": stack sizes sum to ", total, ", header says ",
             interval_count);
    IntervalArray intervals =
        load_intervals(data + at_intervals, size_t(interval_count), std::move(keep));
    return validated_model(f, std::move(materials),
                           StackIndex::from_offsets(offsets.data(), f.cells()),
                           std::move(intervals), what);
}

} // namespace sbrt
