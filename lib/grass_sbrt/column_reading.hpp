/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT read for the columns under map points (virtual
 *            boreholes, profiles): paged within memory=, or the points'
 *            stacks alone
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_COLUMN_READING_HPP
#define SBRT_COLUMN_READING_HPP

#include <array>
#include <cstdint>
#include <vector>

#include "format/block_summary.hpp"
#include "model/model.hpp"

namespace sbrt_grass {

/// \brief How a module reads the columns of an SBRT.
struct ColumnReading {
    uint64_t memory_bytes = 0; ///< memory= in bytes: this process with the blocks it holds
    unsigned threads = 0;      ///< 0: all cores
    /// the blocks are read in order, each once (a block per thread is
    /// then held, not memory='s worth)
    bool blocks_in_order = false;
    /// a map of where the model holds material is drawn (a profile's
    /// location map): the column ranges are read where a member holds
    /// them, so that its columns need no block
    bool tops_map = false;
};

/// SBRT `name` for reading the columns under map points `points` (x, y).
/// A format 2.1 SBRT without property channels is paged: a column's block
/// is decoded when it is read (Model::visit_stack), and the blocks held
/// and this process stay within memory= (else sbrt::Error, thrown by
/// fail_with, says the least that works). Others are read with the points' stacks alone, decoded from the
/// blocks that hold them.
sbrt::Model read_sbrt_columns(const char *name, const std::vector<std::array<double, 2>> &points,
                              const ColumnReading &reading);

/// What a paged read of the model of `summary` holds beside its blocks
/// and ranges (Paging::reserved_bytes): this process's resident memory,
/// and a block each of `threads` threads (0: all cores) may still read
/// after the cache dropped it.
uint64_t reserved_beside_blocks(const sbrt::ModelSummary &summary, unsigned threads);

/// The verbose line of the blocks a paged model decoded; nothing for a
/// model decoded whole.
void report_paging(const sbrt::Model &model);

} // namespace sbrt_grass

#endif
