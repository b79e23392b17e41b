/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Writes an 8-bit RGB image as a PNG file (zlib's deflate),
 *            atomically: a temporary file renamed over the target
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PNG_WRITER_HPP
#define SBRT_PNG_WRITER_HPP

#include <cstdint>
#include <string>
#include <vector>

namespace sbrt {

/// Writes `rgb` (3 bytes per pixel, row-major, top row first) to `path`;
/// throws sbrt::Error when the file cannot be written.
void write_png(const std::string &path, int rows, int cols,
               const std::vector<uint8_t> &rgb);

} // namespace sbrt

#endif
