/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Property channels of a file import, band by band
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "builders/channel_bands.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

ChannelBands::ChannelBands(std::vector<BandGrid> grids, std::vector<std::string> names,
                           ChannelsWriter &writer)
    : grids_(std::move(grids)), names_(std::move(names)), writer_(writer),
      row_values_(grids_.size())
{
    SBRT_CHECK_EQ(grids_.size(), writer.channels().size(), "ChannelBands");
    SBRT_CHECK_EQ(names_.size(), grids_.size(), "ChannelBands");
    for (const ChannelInfo &c : writer.channels())
        no_values_.push_back(c.has_fill ? c.fill : NAN);
}

template <typename T>
void ChannelBands::gather(size_t channel, const T *values, const BandStrides &step,
                          size_t row, size_t first, const ColumnSpan *spans,
                          std::vector<float> &out) const
{
    const BandGrid &grid = grids_[channel];
    const RegularAxis &x = grid.easting, &y = grid.northing, &z = grid.vertical;
    const size_t nx = x.size, ny = y.size, nz = z.size;
    const ptrdiff_t dz = z.ascending ? ptrdiff_t(step.vertical) : -ptrdiff_t(step.vertical);
    const size_t yi = (y.ascending ? ny - 1 - row : row) - first;
    size_t n = 0;
    for (size_t col = 0; col < nx; ++col)
        n += spans[col].size();
    out.resize(n);
    float *to = out.data();
    const float no_value = no_values_[channel];
    for (size_t col = 0; col < nx; ++col) {
        const ColumnSpan span = spans[col];
        if (span.size() == 0)
            continue;
        const size_t xi = x.ascending ? col : nx - 1 - col;
        const ptrdiff_t bottom = ptrdiff_t(yi * step.northing + xi * step.easting +
                                           (z.ascending ? 0 : (nz - 1) * step.vertical));
        for (uint32_t d = span.lo; d < span.hi; ++d) {
            const T value = values[bottom + ptrdiff_t(d) * dz];
            // _FillValue, missing_value and the valid range all mean no
            // value: one marker for them (the fill, or NaN)
            if (grid.missing.is_missing(double(value))) {
                *to++ = no_value;
                continue;
            }
            if constexpr (!std::is_integral_v<T>)
                if (std::isinf(value))
                    fail("property variable '", names_[channel], "' holds ",
                         value > 0 ? "Infinity" : "-Infinity", " at row ", row + 1,
                         ", column ", col + 1, ", depth ", d + 1,
                         " (from the bottom): a channel's values must be finite "
                         "(views colour them by their range); mark such values as "
                         "no data with its valid_max/valid_min (or valid_range) "
                         "attribute, e.g. ncatted -O -a valid_max,", names_[channel],
                         ",o,d,1e30 <file>, or replace them by the _FillValue");
            const float kept = float(value);
            if constexpr (!(std::is_integral_v<T> && sizeof(T) <= 2))
                if (double(kept) != double(value) && !std::isnan(double(value)))
                    fail("channel '", names_[channel], "', row ", row + 1, ", column ",
                         col + 1, ", depth ", d + 1, " (from the bottom): ",
                         double(value),
                         " is not held exactly in 32-bit floating point; channels "
                         "keep values exactly: round or scale the variable first "
                         "(e.g. with ncap2)");
            *to++ = kept;
        }
    }
}

void ChannelBands::add(const std::vector<ColumnSpan> &spans,
                       const std::vector<const void *> &bands,
                       const std::vector<BandStrides> &steps, size_t row0, size_t rows,
                       size_t first)
{
    SBRT_CHECK_EQ(bands.size(), grids_.size(), "ChannelBands::add");
    const size_t nx = grids_.empty() ? 0 : grids_[0].easting.size;
    SBRT_CHECK_EQ(spans.size(), rows * nx, "ChannelBands::add spans");
    // channel by channel on all cores, in runs of rows that end where a
    // row of blocks does (the writer compresses it then)
    for (size_t r0 = 0; r0 < rows;) {
        const size_t run = std::min(rows - r0, size_t(writer_.rows_to_block_end()));
        for_each_row(int(grids_.size()), 0, [&](int ch) {
            for (size_t r = r0; r < r0 + run; ++r) {
                const ColumnSpan *row_spans = spans.data() + r * nx;
                with_sample_type(grids_[size_t(ch)].sample, [&](auto *type) {
                    using T = std::remove_pointer_t<decltype(type)>;
                    gather(size_t(ch), static_cast<const T *>(bands[size_t(ch)]),
                           steps[size_t(ch)], row0 + r, first, row_spans,
                           row_values_[size_t(ch)]);
                });
                writer_.add_channel_row(size_t(ch), row_spans, row_values_[size_t(ch)].data());
            }
        });
        for (size_t r = r0; r < r0 + run; ++r)
            writer_.end_row(spans.data() + r * nx);
        r0 += run;
    }
}

} // namespace sbrt
