/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Property channels of a file import (issue 29): each band's
 *            values over the solid spans of its cells, row by row, into a
 *            ChannelsWriter, whatever the order of the file's indices
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_CHANNEL_BANDS_HPP
#define SBRT_CHANNEL_BANDS_HPP

#include <string>
#include <vector>

#include "builders/band_import.hpp"
#include "format/channels_file.hpp"

namespace sbrt {

/// \brief The bands of every channel into a ChannelsWriter.
class ChannelBands {
public:
    /// One grid (axes as the class variable's, sample type its own) and
    /// name per channel of `writer`.
    ChannelBands(std::vector<BandGrid> grids, std::vector<std::string> names,
                 ChannelsWriter &writer);

    /// Rows [row0, row0 + rows) (row 0 north) whose cells have `spans`
    /// (row by row, as BandImport::record_spans leaves them); per channel
    /// its band (first northing index `first`) and strides. Throws
    /// sbrt::Error naming the channel, row, column and depth of a value a
    /// float32 does not hold exactly, and of an infinite one. Missing
    /// values (the grid's _FillValue, missing_value, outside its valid
    /// range) are stored as the channel's fill, or NaN where it has none.
    void add(const std::vector<ColumnSpan> &spans, const std::vector<const void *> &bands,
             const std::vector<BandStrides> &steps, size_t row0, size_t rows, size_t first);

private:
    template <typename T>
    void gather(size_t channel, const T *values, const BandStrides &step, size_t row,
                size_t first, const ColumnSpan *spans, std::vector<float> &out) const;

    std::vector<BandGrid> grids_;
    std::vector<std::string> names_;
    ChannelsWriter &writer_;
    std::vector<std::vector<float>> row_values_; ///< per channel, one row
    std::vector<float> no_values_; ///< per channel: what a missing value becomes
};

} // namespace sbrt

#endif
