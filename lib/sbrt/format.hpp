/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   On-disk format of an SBRT: a directory with `header` (text,
 *            key: value), `stacks` (binary, checksummed), `cats`, `hist`
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_FORMAT_HPP
#define SBRT_FORMAT_HPP

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "model.hpp"

namespace sbrt {

constexpr uint32_t FORMAT_VERSION = 1;
/// Size of the fixed binary header of `stacks`, magic included.
constexpr uint32_t STACKS_HEADER_SIZE = 8 + 4 + 4 + 6 * 8 + 5 * 4 + 4 + 8 +
                                        3 * 8 + 3 * 4 + 4;

/// Binary `stacks` file:
///   magic "\x89SBRT\r\n\x1a", u32 version, u32 header size,
///   f64 north south east west bottom top, u32 rows cols depths,
///   i32 proj zone, u32 material count, u64 interval count,
///   u64 offsets of materials, counts, intervals,
///   u32 crc32 of materials, counts, intervals, u32 crc32 of the header;
///   materials: i32 class id, u8 red green blue flags (bit 0: has colour);
///   counts: u32 per cell (row 0 north); intervals: u32 material, f32 top.
std::vector<uint8_t> encode_stacks(const Model &model);
/// Decodes untrusted bytes: checks magic, version, sizes, offsets against
/// `size`, checksums and every model invariant; throws sbrt::Error listing
/// what is wrong. `what` names the source in messages. Where `keep` holds
/// `data` alive (a mapped file), the model's intervals are a view of it on
/// little-endian hosts, not a copy.
Model decode_stacks(const uint8_t *data, size_t size, const std::string &what,
                    std::shared_ptr<const void> keep = nullptr);

/// Text `cats`: one "id:label" line per material with a label.
std::string encode_cats(const Model &model);
void decode_cats(const std::string &text, Model &model, const std::string &what);

/// Human-readable `header` (key: value), informational.
std::string encode_header(const Model &model);

/// Writes the SBRT directory atomically; `history` goes to `hist`.
void write_sbrt(const std::string &directory, const Model &model,
                const std::string &history);
/// Reads and validates an SBRT directory.
Model read_sbrt(const std::string &directory);
/// Reads the whole file as bytes (throws if missing or unreadable).
std::vector<uint8_t> read_file_bytes(const std::string &path);

} // namespace sbrt

#endif
