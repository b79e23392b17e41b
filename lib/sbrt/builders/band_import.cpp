/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Band decoding of file imports: runs of equal values per
 *            column, classified once per run
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/band_import.hpp"

#include <type_traits>
#include <vector>

#include "builders/band_classes.hpp"
#include "util/error.hpp"

namespace sbrt {

size_t sample_bytes(SampleType type)
{
    switch (type) {
    case SampleType::int8:
    case SampleType::uint8:
        return 1;
    case SampleType::int16:
    case SampleType::uint16:
        return 2;
    case SampleType::int32:
    case SampleType::uint32:
    case SampleType::float32:
        return 4;
    case SampleType::float64:
        break;
    }
    return 8;
}

void BandImport::add(const void *values, const BandStrides &step, size_t row0,
                     size_t rows, size_t first)
{
    with_sample_type(grid_.sample, [&](auto *type) {
        using T = std::remove_pointer_t<decltype(type)>;
        add_typed(static_cast<const T *>(values), step, row0, rows, first);
    });
}

template <typename T>
void BandImport::add_typed(const T *values, const BandStrides &step, size_t row0,
                           size_t rows, size_t first)
{
    const RegularAxis &x = grid_.easting, &y = grid_.northing, &z = grid_.vertical;
    const size_t nx = x.size, ny = y.size, nz = z.size;
    const MissingValues &missing = grid_.missing;
    BandClasses<T> class_of(missing, classifier_);
    // runs of equal values: a value is classified once per run
    std::vector<ColumnStackBuilder::ClassRun> runs;
    runs.reserve(nz);
    const ptrdiff_t dz = z.ascending ? ptrdiff_t(step.vertical) : -ptrdiff_t(step.vertical);
    if (spans_)
        spans_->clear();
    for (size_t row = row0; row < row0 + rows; ++row) {
        const size_t yi = (y.ascending ? ny - 1 - row : row) - first;
        for (size_t col = 0; col < nx; ++col) {
            const size_t xi = x.ascending ? col : nx - 1 - col;
            // index of the bottom voxel; depth d is at bottom + d * dz
            const ptrdiff_t bottom =
                ptrdiff_t(yi * step.northing + xi * step.easting +
                          (z.ascending ? 0 : (nz - 1) * step.vertical));
            runs.clear();
            size_t d = 0;
            try {
                while (d < nz) {
                    const T value = values[bottom + ptrdiff_t(d) * dz];
                    size_t top = d + 1;
                    while (top < nz && values[bottom + ptrdiff_t(top) * dz] == value)
                        ++top;
                    const int32_t id = class_of(value);
                    if (id == NULL_CLASS && classifier_.has_rules() &&
                        !missing.is_missing(double(value)))
                        unmatched_ += top - d;
                    runs.push_back({id, uint32_t(top)});
                    d = top;
                }
            }
            catch (const Error &e) {
                fail("row ", row + 1, ", column ", col + 1, ", depth ", d + 1,
                     " (from the bottom): ", e.what());
            }
            builder_.add_runs(runs.data(), runs.size());
            if (spans_) {
                // from the bottom of the lowest class run to the top of the highest
                ColumnSpan span;
                size_t last = runs.size();
                while (last > 0 && runs[last - 1].id == NULL_CLASS)
                    --last;
                if (last > 0) {
                    size_t first = 0;
                    while (runs[first].id == NULL_CLASS)
                        ++first;
                    span.lo = first ? runs[first - 1].top : 0;
                    span.hi = runs[last - 1].top;
                }
                spans_->push_back(span);
            }
        }
    }
}

} // namespace sbrt
