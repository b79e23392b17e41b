/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT walked band by band (rows of blocks) within a memory
 *            budget (memory=, MB, GRASS's G_OPT_MEMORYMB): a module that
 *            visits the model's rows in order holds one band at a time
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GRASS_SBRT_BANDS_HPP
#define SBRT_GRASS_SBRT_BANDS_HPP

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "format/format_v2.hpp"
#include "grass.hpp"
#include "module_options.hpp"
#include "model/model.hpp"

namespace sbrt_grass {

/// \brief Bands of whole rows of an SBRT's blocks, each decoded when a row
/// of it is first asked for and dropped when a later band is: the model's
/// rows must be asked for in order (north to south), and every band fits
/// the budget (the stored block summaries size them; without summaries,
/// one row of blocks a band). An SBRT of format 1 is read whole.
class SbrtBands {
public:
    /// Throws sbrt::Error where one row of blocks alone needs more than
    /// `memory` bytes (saying how many it needs). `whole`: the model read
    /// at once, one band of every row, whatever `memory` (for what needs
    /// every column at once: the property channels).
    SbrtBands(const std::string &name, uint64_t memory, unsigned threads,
              std::optional<sbrt::MapArea> area = std::nullopt, bool whole = false);

    /// The whole model's frame and materials.
    const sbrt::Frame &frame() const { return frame_; }
    const std::vector<sbrt::Material> &materials() const { return materials_; }
    const std::string &vertical_datum() const { return vertical_datum_; }
    /// The band holding model row `row` (decoded where it is not the one
    /// held); its cell of (row, col) is band_cell(row, col).
    const sbrt::Model &band_at(int row);
    uint64_t band_cell(int row, int col) const
    {
        return uint64_t(row - band_first_) * uint64_t(frame_.cols) + uint64_t(col);
    }
    /// Past the last model row of the band held.
    int band_end() const { return band_end_; }
    /// Bands decoded so far and the most bytes one took (for reports).
    int bands_read() const { return bands_read_; }
    uint64_t largest_band_bytes() const { return largest_; }

private:
    std::string name_;
    uint64_t memory_;
    unsigned threads_;
    std::optional<sbrt::MapArea> area_;
    sbrt::Frame frame_;
    std::vector<sbrt::Material> materials_;
    std::string vertical_datum_;
    /// first model row of each band, and past the last
    std::vector<int> band_rows_;
    sbrt::Model band_;
    int band_first_ = -1, band_end_ = -1;
    int bands_read_ = 0;
    uint64_t largest_ = 0;
    bool whole_ = false; ///< one band of every row: asked for, or format 1
};

} // namespace sbrt_grass

#endif
