/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What every version of the `stacks` file holds alike: the
 *            magic number and major version it begins with, the frame's
 *            fields and the material table's records
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACKS_FIELDS_HPP
#define SBRT_STACKS_FIELDS_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "format/byte_io.hpp"
#include "model/model.hpp"

namespace sbrt {

/// PNG-style: high bit, name, CR LF, Ctrl-Z (catches text-mode copies).
constexpr uint8_t STACKS_MAGIC[8] = {0x89, 'S', 'B', 'R', 'T', '\r', '\n', 0x1a};

/// The major version of a stacks file, or 0 where the bytes are not one.
inline uint16_t stacks_major_version(const uint8_t *data, size_t size)
{
    if (size < sizeof STACKS_MAGIC + 2 ||
        std::memcmp(data, STACKS_MAGIC, sizeof STACKS_MAGIC) != 0)
        return 0;
    return uint16_t(data[8] | data[9] << 8);
}

/// The frame: f64 north south east west bottom top, u32 rows cols
/// depths, i32 proj zone (68 bytes).
void write_frame(ByteWriter &out, const Frame &frame);
/// Reads and validates the frame (throws naming `what`).
Frame read_frame(ByteReader &in, const std::string &what);

/// The material table: i32 class id, u8 red green blue flags (bit 0: has
/// colour), 8 bytes a material. Labels live in `cats`.
constexpr size_t MATERIAL_RECORD_BYTES = 8;
void write_materials(ByteWriter &out, const std::vector<Material> &materials);
/// `count` records; material 0 is named EMPTY.
std::vector<Material> read_materials(ByteReader &in, uint32_t count);

/// The model of decoded parts once every invariant holds (throws naming
/// `what` and the problems otherwise).
Model validated_model(const Frame &frame, std::vector<Material> materials,
                      StackIndex index, IntervalArray intervals,
                      const std::string &what);

} // namespace sbrt

#endif
