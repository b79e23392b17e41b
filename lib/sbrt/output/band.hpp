/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The outputs of a band of image rows, as the streamed renderer
 *            hands them on: only those asked for are computed and stored
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_HPP
#define SBRT_BAND_HPP

#include <cstdint>
#include <functional>
#include <vector>

namespace sbrt {

/// \brief Which per-pixel outputs a render computes besides the colour.
struct Outputs {
    bool material = false;  ///< class id of the first opaque hit
    bool elevation = false; ///< z of the hit (real map units)
    bool depth = false;     ///< distance from the ray's origin
    bool value = false;     ///< the shown property at the hit (issue 29)
};

/// \brief Rows [first_row, first_row + rows) of an image, row-major, row 0
/// at the top. The vectors of outputs not asked for are empty.
struct Band {
    int first_row = 0, rows = 0, cols = 0;
    std::vector<uint8_t> rgb;      ///< 3 per pixel
    std::vector<int32_t> material; ///< class id, NULL_CLASS where missed
    std::vector<double> elevation; ///< NaN where missed
    std::vector<double> depth;     ///< NaN where missed
    std::vector<double> value;     ///< NaN where missed or without a value
    size_t pixels() const { return size_t(rows) * size_t(cols); }
};

/// Takes the bands of an image, in order from the top, on one thread.
using BandSink = std::function<void(const Band &)>;

} // namespace sbrt

#endif
