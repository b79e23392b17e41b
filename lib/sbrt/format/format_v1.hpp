/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Format v1 of the `stacks` file: uncompressed, 8 bytes an
 *            interval, 4 a cell; read for files written before format v2
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FORMAT_V1_HPP
#define SBRT_FORMAT_V1_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace sbrt {

constexpr uint32_t FORMAT_V1_VERSION = 1;
/// Size of the fixed binary header of a v1 `stacks`, magic included.
constexpr uint32_t STACKS_V1_HEADER_SIZE = 8 + 4 + 4 + 6 * 8 + 5 * 4 + 4 + 8 +
                                           3 * 8 + 3 * 4 + 4;

/// Binary v1 `stacks` file:
///   magic "\x89SBRT\r\n\x1a", u32 version 1, u32 header size,
///   f64 north south east west bottom top, u32 rows cols depths,
///   i32 proj zone, u32 material count, u64 interval count,
///   u64 offsets of materials, counts, intervals,
///   u32 crc32 of materials, counts, intervals, u32 crc32 of the header;
///   materials: i32 class id, u8 red green blue flags (bit 0: has colour);
///   counts: u32 per cell (row 0 north); intervals: u32 material, f32 top.
std::vector<uint8_t> encode_stacks_v1(const Model &model);
/// Decodes untrusted bytes: checks magic, version, sizes, offsets against
/// `size`, checksums and every model invariant; throws sbrt::Error listing
/// what is wrong. `what` names the source in messages. Where `keep` holds
/// `data` alive (a mapped file), the model's intervals are a view of it on
/// little-endian hosts, not a copy.
Model decode_stacks_v1(const uint8_t *data, size_t size, const std::string &what,
                       std::shared_ptr<const void> keep = nullptr);

} // namespace sbrt

#endif
