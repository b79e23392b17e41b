/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A coarse level of detail of a model, for frames drawn while
 *            the camera moves (issue 49, item 4): the same extent in fewer,
 *            larger cells, each cell the exact stack of one fine cell
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_LEVEL_OF_DETAIL_HPP
#define SBRT_LEVEL_OF_DETAIL_HPP

#include <cstdint>

#include "model/model.hpp"

namespace sbrt {

/// Models of fewer cells than this (512 x 512) get no coarse level.
constexpr uint64_t LOD_MIN_CELLS = 512 * 512;
/// The most cells a coarse level has.
constexpr uint64_t LOD_MAX_CELLS = 500000;

/// \brief The factor of the coarse level of a model on `frame`: the
/// smallest power of two (2 or more) whose coarse grid has at most
/// LOD_MAX_CELLS cells; 1 (no coarse level) for a model of fewer than
/// LOD_MIN_CELLS cells.
int level_of_detail_factor(const Frame &frame);

/// \brief The model on the same extent in ceil(rows / factor) x
/// ceil(cols / factor) cells, each coarse cell holding the stack of the
/// fine cell under its centre (exact per sample: no class is averaged);
/// materials, vertical frame and datum unchanged. `factor` >= 1 (1: a
/// copy). Throws sbrt::Error for a factor below 1.
Model coarsened(const Model &model, int factor);

/// \brief coarsened() band by band of fine rows: an import that holds a
/// band of the model at a time builds its coarse level as it goes.
class CoarseLevelBuilder {
public:
    /// For the model on `fine` at `factor` (>= 1; throws sbrt::Error else).
    CoarseLevelBuilder(const Frame &fine, int factor);
    /// The fine model's rows [first_row, first_row + band rows), held by
    /// `band` as a model of their own; bands come in order. Takes the
    /// coarse rows whose fine row lies in them.
    void add_rows(const Model &band, int first_row);
    /// The coarse model (vertical datum left to the caller), once every
    /// fine row was given; throws sbrt::Error else.
    Model finish(std::vector<Material> materials);

private:
    Frame fine_, frame_;
    std::vector<int> fine_cols_; ///< the fine column under each coarse one
    int next_row_ = 0;           ///< the first coarse row not yet built
    std::vector<uint32_t> offsets_;
    Intervals intervals_;
};

} // namespace sbrt

#endif
