/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT directory written band by band of rows: the stacks
 *            and each column's range as the bands come, the directory
 *            appearing whole at the end (write_sbrt, and imports that hold
 *            a band of the model, not the model)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_SBRT_WRITER_HPP
#define SBRT_SBRT_WRITER_HPP

#include <string>
#include <vector>

#include "format/atomic_dir.hpp"
#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"
#include "format/stacks_writer.hpp"
#include "model/model.hpp"

namespace sbrt {

/// \brief The members of an SBRT directory, staged beside `directory`
/// until finish() swaps them in; destroyed without finish(), it leaves
/// `directory` as it was.
class SbrtWriter {
public:
    SbrtWriter(const std::string &directory, const Frame &frame,
               const StacksV2Options &options = {});

    /// The model's next rows as a model of their own (StacksWriter::add_rows).
    void add_rows(const Model &band);
    int rows_done() const { return stacks_.rows_done(); }
    uint64_t intervals() const { return stacks_.intervals(); }
    uint64_t solid_intervals() const { return stacks_.solid_intervals(); }

    /// \brief What the directory holds beside the stacks.
    struct Legend {
        std::vector<Material> materials; ///< the whole model's, EMPTY first
        std::string vertical_datum;      ///< empty: none
    };
    /// Writes `stacks`, `ranges`, `tops`, `header`, `cats`, `colors`, `datum`
    /// (where the model has one) and `hist` (`history`); where
    /// `channels_file` is given, that finished channels file (written for
    /// this frame with the stacks' block size) moves in as `channels`;
    /// where `coarse` is given (the coarse level of detail), it is written
    /// as `stacks_lod`. Then swaps the directory in. Throws sbrt::Error.
    void finish(const Legend &legend, const std::string &history,
                const std::string &channels_file = {}, const Model *coarse = nullptr);

private:
    AtomicDirectory out_;
    Frame frame_;
    StacksV2Options options_;
    StacksWriter stacks_;
    ColumnRangesEncoder ranges_; ///< each column's, row by row
    ColumnTopsEncoder tops_;     ///< each column's top interval, row by row
};

} // namespace sbrt

#endif
