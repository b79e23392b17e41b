/****************************************************************************
 * MODULE:    testsuite/fuzz (r3.sbrt addon)
 * PURPOSE:   libFuzzer target of the SBRT reader (formats v1 and v2): decode_stacks and
 *            decode_cats, a paged model's opening (every block decoded) and
 *            the `ranges` and `tops` members on untrusted bytes must end in a model or an
 *            sbrt::Error, never a crash, a hang or undefined behaviour.
 *            Bit 0 of the first byte recomputes the checksums, so that the
 *            fuzzer also reaches what lies behind them.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <zlib.h>

#include "util/error.hpp"
#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/format.hpp"
#include "format/paged_stacks.hpp"
#include "format/stacks_fields.hpp"

namespace {

uint64_t get_u64(const std::vector<uint8_t> &b, size_t at)
{
    uint64_t v = 0;
    for (int k = 7; k >= 0; --k)
        v = v << 8 | b[at + size_t(k)];
    return v;
}

void put_u32(std::vector<uint8_t> &b, size_t at, uint32_t v)
{
    for (int k = 0; k < 4; ++k)
        b[at + size_t(k)] = uint8_t(v >> (8 * k));
}

uint32_t crc_of(const std::vector<uint8_t> &b, uint64_t from, uint64_t to)
{
    return uint32_t(crc32(0, b.data() + from, uInt(to - from)));
}

/// The checksums a v1 file would need (format_v1.hpp): the sections'
/// where their offsets lie in the data, then the header's.
void fix_v1_checksums(std::vector<uint8_t> &b)
{
    const size_t header = sbrt::STACKS_V1_HEADER_SIZE;
    if (b.size() < header)
        return;
    const uint64_t materials = get_u64(b, 96), counts = get_u64(b, 104),
                   intervals = get_u64(b, 112);
    if (materials <= counts && counts <= intervals && intervals <= b.size()) {
        put_u32(b, 120, crc_of(b, materials, counts));
        put_u32(b, 124, crc_of(b, counts, intervals));
        put_u32(b, 128, crc_of(b, intervals, b.size()));
    }
    put_u32(b, header - 4, crc_of(b, 0, header - 4));
}

/// The checksums a v2 file would need (format_v2.hpp): each block's where
/// it lies in the data, the block table's, the materials', the header's.
void fix_v2_checksums(std::vector<uint8_t> &b)
{
    if (b.size() < sbrt::STACKS_V2_HEADER_SIZE)
        return;
    const uint32_t header = uint32_t(get_u64(b, 12) & 0xffffffffu);
    if (header < sbrt::STACKS_V2_HEADER_SIZE || header > b.size())
        return;
    const uint64_t materials = get_u64(b, 116), table = get_u64(b, 124);
    if (table <= b.size()) {
        for (uint64_t e = table; e + 24 <= b.size(); e += 24) {
            const uint64_t at = get_u64(b, size_t(e));
            const uint64_t size = get_u64(b, size_t(e + 8)) & 0xffffffffu;
            if (at <= b.size() && size <= b.size() - at)
                put_u32(b, size_t(e + 20), crc_of(b, at, at + size));
        }
        put_u32(b, 144, crc_of(b, table, b.size()));
        const uint32_t count = uint32_t(get_u64(b, 92) & 0xffffffffu);
        if (materials <= table && count <= (table - materials) / 8)
            put_u32(b, 140, crc_of(b, materials, materials + 8ull * count));
    }
    put_u32(b, header - 4, crc_of(b, 0, header - 4));
}

/// Whether `b` starts as a per-column member of `magic` (its header whole).
bool is_member(const std::vector<uint8_t> &b, const char *magic)
{
    return b.size() >= 52 && std::memcmp(b.data(), magic, 8) == 0;
}

void fix_checksums(std::vector<uint8_t> &b)
{
    if (is_member(b, "SBRTRNG1") || is_member(b, "SBRTTOP1")) {
        put_u32(b, 48, crc_of(b, 52, b.size()));
        return;
    }
    const uint16_t major = sbrt::stacks_major_version(b.data(), b.size());
    if (major == 1)
        fix_v1_checksums(b);
    else if (major == 2)
        fix_v2_checksums(b);
}

/// The bytes opened as a paged model (every block decoded once for the
/// column ranges), within 64 MiB, on one thread.
void open_paged(const std::vector<uint8_t> &bytes)
{
    try {
        sbrt::Paging paging;
        paging.budget_bytes = 64u << 20;
        paging.threads = 1;
        sbrt::open_paged_model(bytes.data(), bytes.size(), "fuzz", nullptr, paging);
    }
    catch (const sbrt::Error &) {
    }
}

/// The grid (at most 2^22 cells, 100 depths) and stacks a per-column
/// member names.
sbrt::Frame member_frame(const std::vector<uint8_t> &bytes, sbrt::StacksStamp &stamp)
{
    sbrt::Frame frame;
    frame.rows = std::max(1, int(get_u64(bytes, 8) & 0xfffu));
    frame.cols = std::max(1, int(get_u64(bytes, 12) & 0x3ffu));
    frame.depths = 100;
    stamp.end = get_u64(bytes, 20);
    stamp.intervals = get_u64(bytes, 28);
    stamp.table_crc = uint32_t(get_u64(bytes, 36) & 0xffffffffu);
    return frame;
}

/// The bytes as a `ranges` member, for the grid and stacks it names.
void read_ranges_member(const std::vector<uint8_t> &bytes)
{
    if (!is_member(bytes, "SBRTRNG1"))
        return;
    sbrt::StacksStamp stamp;
    const sbrt::Frame frame = member_frame(bytes, stamp);
    try {
        sbrt::decode_column_ranges(bytes.data(), bytes.size(), "fuzz", frame, stamp);
    }
    catch (const sbrt::Error &) {
    }
}

/// The bytes as a `tops` member, for the grid and stacks it names, every
/// column's range [0, 100) and 5 materials.
void read_tops_member(const std::vector<uint8_t> &bytes)
{
    if (!is_member(bytes, "SBRTTOP1"))
        return;
    sbrt::StacksStamp stamp;
    const sbrt::Frame frame = member_frame(bytes, stamp);
    // held compact, as a paged voxel model holds them
    const sbrt::ColumnRangeArray ranges(
        sbrt::CompactRanges(frame.cells(), sbrt::CompactRange{0, 100}));
    try {
        sbrt::column_tops_bytes(bytes.data(), bytes.size(), frame, "fuzz");
        sbrt::decode_column_tops(bytes.data(), bytes.size(), "fuzz", frame, stamp, ranges, 5,
                                 1);
    }
    catch (const sbrt::Error &) {
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    std::vector<uint8_t> bytes(data + 1, data + size);
    if (data[0] & 1)
        fix_checksums(bytes);
    try {
        // one thread, and models of at most 256 MiB (libFuzzer's malloc limit
        // is its RSS limit)
        sbrt::ReadOptions options;
        options.threads = 1;
        options.memory_limit = 256u << 20;
        open_paged(bytes);
        read_ranges_member(bytes);
        read_tops_member(bytes);
        sbrt::Model model =
            sbrt::decode_stacks(bytes.data(), bytes.size(), "fuzz", nullptr, options);
        // the same bytes as a cats file of the decoded model
        sbrt::decode_cats(std::string(bytes.begin(), bytes.end()), model, "fuzz");
    }
    catch (const sbrt::Error &) {
    }
    return 0;
}
