/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   Writes a format v2 stacks file band by band of rows: each
 *            band's blocks are compressed as it comes and only their
 *            compressed bytes are held, so that an import writes a model
 *            larger than memory from bands of it
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACKS_WRITER_HPP
#define SBRT_STACKS_WRITER_HPP

#include <cstdint>
#include <vector>

#include "format/block_summary.hpp"
#include "format/byte_sink.hpp"
#include "format/format_v2.hpp"
#include "format/stacks_v2_layout.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief The stacks of a model on `frame`, given as bands of rows and
/// laid out as one file at finish(), once the materials and the field
/// widths are known. The file is the same, byte for byte, as
/// write_stacks_v2 writes of the whole model.
class StacksWriter {
public:
    /// Throws sbrt::Error for a block size outside 1..MAX_BLOCK_SIZE.
    StacksWriter(const Frame &frame, const StacksV2Options &options);

    /// The model's rows [rows_done(), rows_done() + band rows): `band` holds
    /// them as a model of their own (its frame frame_rows of the model's);
    /// its materials are those of the model so far (an index never changes
    /// meaning). Every band but the last holds a multiple of the block
    /// size of rows. Compresses the band's blocks on options.threads
    /// threads; throws sbrt::Error for a band out of order or shape.
    void add_rows(const Model &band);
    /// Rows given so far.
    int rows_done() const { return rows_done_; }
    /// Intervals given so far, and of them not EMPTY.
    uint64_t intervals() const { return intervals_; }
    uint64_t solid_intervals() const { return solid_intervals_; }

    /// Writes the file into `sink` (header, materials, blocks, the 2.1
    /// block summaries, block table); `materials` those of the whole model
    /// (EMPTY first). Blocks compressed with narrower widths than the
    /// whole model needs are recompressed first; `optional_features`
    /// (V2_OPTIONAL_*) are set beside those of the options. Throws
    /// sbrt::Error where a row is missing or a band used a material
    /// `materials` lacks.
    void finish(ByteSink &sink, const std::vector<Material> &materials,
                uint32_t optional_features = 0);

private:
    /// A block as compressed, and the widths it was encoded with.
    struct StoredBlock {
        std::vector<uint8_t> bytes;
        BlockEntry entry;
        StacksV2Widths widths;
    };

    Frame frame_;
    StacksV2Options options_;
    BlockGrid grid_;
    int rows_done_ = 0;
    uint64_t intervals_ = 0, solid_intervals_ = 0;
    /// The widest fields a band needed so far; materials given so far.
    StacksV2Widths widths_;
    size_t materials_seen_ = 1;
    std::vector<StoredBlock> blocks_;
    std::vector<BlockSummary> summaries_;
};

} // namespace sbrt

#endif
