/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   What every version of the `stacks` file begins with: the
 *            magic number and the major version (u16 after the magic)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACKS_PREFIX_HPP
#define SBRT_STACKS_PREFIX_HPP

#include <cstddef>
#include <cstdint>
#include <cstring>

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

} // namespace sbrt

#endif
