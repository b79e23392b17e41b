/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT directory written band by band of rows
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/sbrt_writer.hpp"

#include <cstdio>

#include "format/byte_sink.hpp"
#include "format/channels_file.hpp"
#include "format/column_ranges_file.hpp"
#include "format/format.hpp"
#include "format/mapped_file.hpp"
#include "format/member_dir.hpp"
#include "model/column_ranges.hpp"
#include "util/error.hpp"

namespace sbrt {

SbrtWriter::SbrtWriter(const std::string &directory, const Frame &frame,
                       const StacksV2Options &options)
    : out_(directory), frame_(frame), options_(options), stacks_(frame, options), ranges_(frame),
      tops_(frame)
{
}

void SbrtWriter::add_rows(const Model &band)
{
    stacks_.add_rows(band);
    ranges_.add(column_ranges(band));
    tops_.add(column_tops(band));
}

void SbrtWriter::finish(const Legend &legend, const std::string &history,
                        const std::string &channels_file, const Model *coarse)
{
    StacksV2Options options = options_;
    size_t channels = 0;
    if (!channels_file.empty()) {
        // the channels must fit this frame and its blocks before they move in
        channels = channels_for_stacks(MappedFile(channels_file, MappedFile::Pages::on_demand),
                                       frame_, options.block_size, channels_file);
        options.optional_features |= V2_OPTIONAL_CHANNELS;
        const std::string target = out_.file_path("channels");
        if (std::rename(channels_file.c_str(), target.c_str()) != 0)
            out_.copy_file("channels", open_regular_file(channels_file), channels_file);
    }
    FileSink stacks(out_.file_path("stacks"));
    stacks_.finish(stacks, legend.materials, options.optional_features);
    stacks.finish();
    {
        // each column's range and top interval, stamped with the stacks
        // written: a paged model opens without decoding a block, and a ray
        // that meets only the top of a column needs none
        const std::string path = out_.file_path("stacks");
        const MappedFile written(open_regular_file(path), path, MappedFile::Pages::on_demand);
        const StacksStamp stamp = stacks_stamp(written.data(), written.size(), path);
        out_.write_file("ranges", ranges_.finish(stamp));
        out_.write_file("tops", tops_.finish(stamp));
    }
    if (coarse) {
        // a complete stacks file of its own (no channels: those are the
        // exact model's)
        StacksV2Options coarse_options = options_;
        coarse_options.optional_features &= ~V2_OPTIONAL_CHANNELS;
        coarse->validate();
        FileSink lod(out_.file_path("stacks_lod"));
        write_stacks_v2(lod, *coarse, coarse_options);
        lod.finish();
    }
    out_.write_file("header", encode_header(frame_, legend.materials.size(),
                                            stacks_.intervals(), channels));
    out_.write_file("cats", encode_cats(legend.materials));
    out_.write_file("colors", encode_colors(legend.materials));
    if (!legend.vertical_datum.empty())
        out_.write_file("datum", encode_datum(legend.vertical_datum));
    out_.write_file("hist", history);
    out_.commit();
}

} // namespace sbrt
