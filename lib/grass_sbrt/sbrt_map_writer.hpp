/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT map written band by band of rows, under the writers'
 *            lock, with its history and coarse level of detail: an import
 *            holds a band of the model, not the model (issue 49, item 2)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef GRASS_SBRT_MAP_WRITER_HPP
#define GRASS_SBRT_MAP_WRITER_HPP

#include <optional>
#include <string>

#include "format/sbrt_lock.hpp"
#include "format/sbrt_writer.hpp"
#include "scene/level_of_detail.hpp"

namespace sbrt_grass {

/// \brief SBRT `name` of `frame` written into `path` (new_sbrt_path): each
/// band of rows compressed as it comes, the map appearing whole at
/// finish(). Holds the writers' lock from construction on. A failure to
/// lock, stage or write is a G_fatal_error naming the map (add_rows
/// throws, so that a caller first stops what it runs beside); a fatal
/// error before finish() (here or anywhere in the module) removes what
/// was staged.
class SbrtMapWriter {
public:
    SbrtMapWriter(const char *name, const std::string &path, const sbrt::Frame &frame,
                  unsigned threads);
    ~SbrtMapWriter();
    SbrtMapWriter(const SbrtMapWriter &) = delete;
    SbrtMapWriter &operator=(const SbrtMapWriter &) = delete;

    /// Rows a band holds so that the stacks' blocks stay whole: give bands
    /// of a multiple of this (the last band: what is left).
    int block_rows() const { return block_rows_; }
    /// The model's next rows as a model of their own
    /// (sbrt::StacksWriter::add_rows); throws sbrt::Error.
    void add_rows(const sbrt::Model &band);
    int rows_done() const { return writer_->rows_done(); }
    uint64_t solid_intervals() const { return writer_->solid_intervals(); }
    /// Writes the map: `legend` the whole model's, history naming
    /// `source`, `channels_file` (a finished channels file for this frame)
    /// moved in where given.
    void finish(const sbrt::SbrtWriter::Legend &legend, const std::string &source,
                const std::string &channels_file = {});

private:
    static void discard(void *self);

    std::string name_;
    sbrt::SbrtLock lock_;
    std::optional<sbrt::SbrtWriter> writer_;
    int block_rows_;
    /// the coarse level for frames drawn while the camera moves
    int factor_ = 1;
    std::optional<sbrt::CoarseLevelBuilder> coarse_;
};

} // namespace sbrt_grass

#endif
