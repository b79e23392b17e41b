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

#include "util/unfilled_allocator.hpp"

namespace sbrt {

/// \brief Which per-pixel outputs a render computes besides the colour.
struct Outputs {
    bool material = false;  ///< class id of the first opaque hit
    bool elevation = false; ///< z of the hit (real map units)
    bool depth = false;     ///< distance from the ray's origin
    bool value = false;     ///< the shown property at the hit (issue 29)
};

/// \brief Rows of one output of a band: row r starts `stride` elements
/// after row r - 1 (a pixel is 3 elements of the RGB plane, 1 of the
/// others). Empty where the output was not asked for. It views memory it
/// does not own: the band's own store (the CPU's), or the buffer the GPU
/// wrote the band into, mapped into host memory (sbrt_gl::MappedBands).
template <typename T>
class BandPlane {
public:
    BandPlane() = default;
    BandPlane(T *first, size_t stride) : first_(first), stride_(stride) {}
    bool empty() const { return first_ == nullptr; }
    T *row(int r) const { return first_ + size_t(r) * stride_; }
    size_t stride() const { return stride_; }

private:
    T *first_ = nullptr;
    size_t stride_ = 0;
};

/// \brief Rows [first_row, first_row + rows) of an image, row 0 at the top.
/// The planes of outputs not asked for are empty. A band the CPU fills
/// keeps its rows in `store`, row after row; a band the GPU shaded views
/// the GPU's mapped buffer, whose RGB rows start on whole 4-byte words
/// (stride may exceed 3 cols). Moves keep the planes valid; no copies.
struct Band {
    int first_row = 0, rows = 0, cols = 0;
    BandPlane<uint8_t> rgb;        ///< 3 bytes a pixel
    BandPlane<int32_t> material;   ///< class id, NULL_CLASS where missed
    BandPlane<double> elevation;   ///< NaN where missed
    BandPlane<double> depth;       ///< NaN where missed
    BandPlane<double> value;       ///< NaN where missed or without a value
    /// The memory of a band the CPU fills (prepare_band); unused where the
    /// planes lie in the GPU's buffer.
    struct Store {
        std::vector<uint8_t, UnfilledAllocator<uint8_t>> rgb;
        std::vector<int32_t, UnfilledAllocator<int32_t>> material;
        std::vector<double, UnfilledAllocator<double>> elevation, depth, value;
    } store;

    Band() = default;
    Band(Band &&) = default;
    Band &operator=(Band &&) = default;
    Band(const Band &) = delete;
    Band &operator=(const Band &) = delete;

    size_t pixels() const { return size_t(rows) * size_t(cols); }
    /// Bytes of the outputs of one pixel (3 of RGB and those asked for).
    size_t bytes_per_pixel() const
    {
        return 3 + (material.empty() ? 0 : 4) + (elevation.empty() ? 0 : 8) +
               (depth.empty() ? 0 : 8) + (value.empty() ? 0 : 8);
    }
};

/// Takes the bands of an image, in order from the top, on one thread.
using BandSink = std::function<void(const Band &)>;

} // namespace sbrt

#endif
