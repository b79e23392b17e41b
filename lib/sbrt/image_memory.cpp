/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The renderer's memory model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "image_memory.hpp"

#include <algorithm>

#include "tracing/tracer.hpp"
#include "util/available_memory.hpp"
#include "util/error.hpp"

namespace sbrt {

namespace {

/// Output bytes per pixel of a band: rgb 3, class 4, elevation 8, depth 8.
constexpr double OUTPUT_BYTES = 23;
/// The kernel's depths and smoothing per pixel.
constexpr double KERNEL_BYTES = 32;
/// Rows of a band at most (lib/sbrt/renderer.cpp).
constexpr int BAND_ROWS = 64;
/// The share of the available memory an image may take: the model, the
/// maps being written, GRASS and the page cache need the rest.
constexpr double IMAGE_SHARE = 0.5;

} // namespace

double image_bytes(int rows, int cols, const ImageNeeds &needs)
{
    const double per_pixel = double(sizeof(Hit)) + OUTPUT_BYTES;
    const double pixels = double(rows) * double(cols);
    const double streamed =
        needs.kernel_normals ? pixels * (per_pixel + KERNEL_BYTES)
                             : 2.0 * std::min(rows, BAND_ROWS) * double(cols) * per_pixel;
    return streamed + pixels * needs.whole_image_bytes_per_pixel;
}

void check_image_fits(int rows, int cols, const ImageNeeds &needs)
{
    const double needed = image_bytes(rows, cols, needs);
    const double memory = available_memory();
    if (memory > 0 && needed > IMAGE_SHARE * memory)
        fail("An image of ", cols, " x ", rows, " pixels needs about ", needed / 1e9,
             " GB of memory for its rays and outputs",
             needs.kernel_normals ? " with normals=kernel" : "",
             needs.whole_image_bytes_per_pixel ? " and the whole image's colours" : "",
             "; this machine has ", memory / 1e9, " GB available (an image may take ",
             int(IMAGE_SHARE * 100), " % of it). Render a smaller image (size=, or for view=top "
             "g.region rows= cols=) or use a larger machine.");
}

} // namespace sbrt
