/****************************************************************************
 * MODULE:    testsuite/fuzz (r3.sbrt addon)
 * PURPOSE:   libFuzzer target of the SBRT reader: decode_stacks and
 *            decode_cats on untrusted bytes must end in a model or an
 *            sbrt::Error, never a crash, a hang or undefined behaviour.
 *            Bit 0 of the first byte recomputes the checksums, so that the
 *            fuzzer also reaches what lies behind them.
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>
#include <string>
#include <vector>

#include <zlib.h>

#include "error.hpp"
#include "format.hpp"

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

/// The checksums the bytes would need (layout of format.hpp): the
/// sections' where their offsets lie in the data, then the header's.
void fix_checksums(std::vector<uint8_t> &b)
{
    const size_t header = sbrt::STACKS_HEADER_SIZE;
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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    std::vector<uint8_t> bytes(data + 1, data + size);
    if (data[0] & 1)
        fix_checksums(bytes);
    try {
        sbrt::Model model = sbrt::decode_stacks(bytes.data(), bytes.size(), "fuzz");
        // the same bytes as a cats file of the decoded model
        sbrt::decode_cats(std::string(bytes.begin(), bytes.end()), model, "fuzz");
    }
    catch (const sbrt::Error &) {
    }
    return 0;
}
