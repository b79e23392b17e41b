/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The renderer's memory model: what an image of rows x cols
 *            takes while it is rendered, checked against what the machine
 *            can still give before the first pixel
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_IMAGE_MEMORY_HPP
#define SBRT_IMAGE_MEMORY_HPP

#include <cstdint>

namespace sbrt {

/// \brief What the caller keeps beside the renderer's own buffers.
struct ImageNeeds {
    bool kernel_normals = false; ///< the kernel's window may reach the whole image
    /// bytes per pixel the caller holds for the whole image (an annotated
    /// PNG's RGB: 3; the view server's frame: 3; 0 where it streams)
    unsigned whole_image_bytes_per_pixel = 0;
};

/// Bytes an image of rows x cols needs while rendering: two bands in flight,
/// each of hits (sizeof(Hit)) and outputs (rgb, class, elevation, depth: 23
/// bytes) per pixel, 64 rows at most; with kernel normals the kernel's
/// window at its largest (the whole image, with its depths and smoothing:
/// 32 bytes more); plus what the caller keeps of the whole image.
double image_bytes(int rows, int cols, const ImageNeeds &needs);

/// Throws sbrt::Error, with both figures and what to do, unless an image of
/// rows x cols fits in half of available_memory() (util/available_memory.hpp) (the model, the maps
/// written, GRASS and the page cache need the rest).
void check_image_fits(int rows, int cols, const ImageNeeds &needs);

} // namespace sbrt

#endif
