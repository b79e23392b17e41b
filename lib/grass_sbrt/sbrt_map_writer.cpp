/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT map written band by band of rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_map_writer.hpp"

#include "util/error.hpp"

#include "grass.hpp"
#include "raster_metadata.hpp"
#include "sbrt_store.hpp"

namespace sbrt_grass {

namespace {

sbrt::StacksV2Options stacks_options(unsigned threads)
{
    sbrt::StacksV2Options options;
    options.threads = threads;
    return options;
}

/// The writers' lock of `path`, or a fatal error naming map `name`.
sbrt::SbrtLock locked(const char *name, const std::string &path)
{
    try {
        return lock_for_writing(path);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Unable to write SBRT <%s>: %s"), name, e.what());
    }
}

} // namespace

SbrtMapWriter::SbrtMapWriter(const char *name, const std::string &path,
                             const sbrt::Frame &frame, unsigned threads)
    : name_(name), lock_(locked(name, path)), block_rows_(stacks_options(threads).block_size)
{
    try {
        writer_.emplace(path, frame, stacks_options(threads));
        factor_ = sbrt::level_of_detail_factor(frame);
        if (factor_ > 1)
            coarse_.emplace(frame, factor_);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Unable to write SBRT <%s>: %s"), name, e.what());
    }
    G_add_error_handler(discard, this);
}

SbrtMapWriter::~SbrtMapWriter()
{
    G_remove_error_handler(discard, this);
}

void SbrtMapWriter::discard(void *self)
{
    static_cast<SbrtMapWriter *>(self)->writer_.reset();
}

void SbrtMapWriter::add_rows(const sbrt::Model &band)
{
    const int first = writer_->rows_done();
    writer_->add_rows(band);
    if (coarse_)
        coarse_->add_rows(band, first);
}

void SbrtMapWriter::finish(const sbrt::SbrtWriter::Legend &legend, const std::string &source,
                           const std::string &channels_file)
{
    std::string history = "created: " + history_date() + "\n";
    history += std::string("creator: ") + G_whoami() + "\n";
    history += "source: " + source + "\n";
    history += std::string("command: ") + G_recreate_command() + "\n";
    try {
        std::optional<sbrt::Model> coarse;
        if (coarse_) {
            coarse = coarse_->finish(legend.materials);
            coarse->set_vertical_datum(legend.vertical_datum);
            G_verbose_message(_("Coarse level of detail: %d x %d cells (1 in %d a side)"),
                              coarse->frame().rows, coarse->frame().cols, factor_);
            coarse_.reset();
        }
        writer_->finish(legend, history, channels_file, coarse ? &*coarse : nullptr);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error(_("Unable to write SBRT <%s>: %s"), name_.c_str(), e.what());
    }
}

} // namespace sbrt_grass
