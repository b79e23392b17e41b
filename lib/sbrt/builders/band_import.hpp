/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Bands of a gridded file variable (whole columns of a range of
 *            northing indices, in the file's own index order and sample
 *            type) -> the columns of a ColumnStackBuilder
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_BAND_IMPORT_HPP
#define SBRT_BAND_IMPORT_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

#include "builders/classifier.hpp"
#include "builders/column_builder.hpp"
#include "builders/grid_axes.hpp"
#include "builders/missing_values.hpp"
#include "model/property_channel.hpp"

namespace sbrt {

/// The types a band's values come in.
enum class SampleType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// Bytes of one value of `type`.
size_t sample_bytes(SampleType type);

/// Calls f with a null pointer of the C++ type of `type` (int16_t * for
/// int16, ...): code templated on the value type, chosen at run time.
template <typename F>
void with_sample_type(SampleType type, F &&f)
{
    switch (type) {
    case SampleType::int8:
        return f(static_cast<int8_t *>(nullptr));
    case SampleType::uint8:
        return f(static_cast<uint8_t *>(nullptr));
    case SampleType::int16:
        return f(static_cast<int16_t *>(nullptr));
    case SampleType::uint16:
        return f(static_cast<uint16_t *>(nullptr));
    case SampleType::int32:
        return f(static_cast<int32_t *>(nullptr));
    case SampleType::uint32:
        return f(static_cast<uint32_t *>(nullptr));
    case SampleType::float32:
        return f(static_cast<float *>(nullptr));
    case SampleType::float64:
        return f(static_cast<double *>(nullptr));
    }
}

/// \brief Element strides of the easting, northing and vertical indices in
/// a band (a band's first northing index is its own index 0).
struct BandStrides {
    size_t easting = 0, northing = 0, vertical = 0;
};

/// \brief What band decoding needs of a file variable: its axes (in the
/// file's index order and direction), missing values and sample type.
struct BandGrid {
    RegularAxis easting, northing, vertical;
    MissingValues missing;
    SampleType sample = SampleType::float64;
};

/// \brief Bands of a file variable into a ColumnStackBuilder: rows north
/// to south, columns west to east, depths bottom up, whatever the order of
/// the file's indices.
class BandImport {
public:
    BandImport(const BandGrid &grid, Classifier &classifier, ColumnStackBuilder &builder)
        : grid_(grid), classifier_(classifier), builder_(builder)
    {
    }

    /// Rows [row0, row0 + rows) (row 0 north) of a band of grid.sample
    /// values whose first northing index is `first`. Throws sbrt::Error
    /// naming the row, column and depth of a value that makes no class.
    void add(const void *values, const BandStrides &step, size_t row0, size_t rows,
             size_t first);

    /// Voxels with a value no rule covered (they became empty).
    uint64_t unmatched() const { return unmatched_; }
    /// Where given, each add() leaves there the solid span of every cell it
    /// added (row by row): the voxels property channels are kept for.
    void record_spans(std::vector<ColumnSpan> *spans) { spans_ = spans; }

private:
    template <typename T>
    void add_typed(const T *values, const BandStrides &step, size_t row0, size_t rows,
                   size_t first);

    const BandGrid &grid_;
    Classifier &classifier_;
    ColumnStackBuilder &builder_;
    uint64_t unmatched_ = 0;
    std::vector<ColumnSpan> *spans_ = nullptr;
};

} // namespace sbrt

#endif
