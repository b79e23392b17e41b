/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT walked band by band within memory=
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "sbrt_bands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "format/block_summary.hpp"
#include "grass.hpp"
#include "sbrt_store.hpp"
#include "util/error.hpp"

namespace sbrt_grass {

namespace {

constexpr uint64_t MB = uint64_t(1) << 20;
/// Rows a band holds where the stacks have no block summaries to size it
/// (the writer's default block size).
constexpr int UNSIZED_BAND_ROWS = 64;
/// The most bytes a band takes, whatever the budget: small bands are
/// faster, not only leaner (national model, r3.sbrt.surface: 32 bands of
/// 17 MB 3.9 s, one of 432 MB 6.4 s: the pages of a band are touched
/// fresh, those of a smaller one come back from the allocator warm).
constexpr uint64_t BAND_BYTES = uint64_t(32) << 20;

/// Bytes decoding rows of `cells` cells and `intervals` intervals takes,
/// as the reader holds them against its memory_limit.
uint64_t band_bytes(uint64_t cells, uint64_t intervals, unsigned count_bytes,
                    unsigned record_bytes)
{
    return uint64_t(std::ceil(sbrt::decoded_bytes(cells, intervals, count_bytes, record_bytes)));
}

} // namespace

SbrtBands::SbrtBands(const std::string &name, uint64_t memory, unsigned threads,
                     std::optional<sbrt::MapArea> area, bool whole)
    : name_(name), memory_(memory), threads_(threads), area_(area), whole_(whole)
{
    if (whole_) { // the one band now: its frame, materials and datum
        band_at(0);
        frame_ = band_.frame();
        materials_ = band_.materials();
        vertical_datum_ = band_.vertical_datum();
        return;
    }
    const std::optional<sbrt::ModelSummary> summary = read_sbrt_summary_map(name.c_str());
    if (!summary) {
        // no summaries (format 2.0 or 1): the frame from a read that
        // decodes no stack, then bands of a block row each, refused by the
        // reader where one needs more than the budget
        sbrt::ReadOptions nothing;
        nothing.points.emplace();
        sbrt::Model frame_only = read_sbrt_map(name.c_str(), nothing);
        frame_ = frame_only.frame();
        materials_ = frame_only.materials();
        vertical_datum_ = frame_only.vertical_datum();
        for (int row = 0; row < frame_.rows; row += UNSIZED_BAND_ROWS)
            band_rows_.push_back(row);
        band_rows_.push_back(frame_.rows);
        whole_ = frame_only.intervals().is_view(); // format 1: read in place, whole
        return;
    }
    frame_ = summary->frame;
    materials_ = summary->materials;
    vertical_datum_ = summary->vertical_datum;
    // rows of blocks joined into bands while they fit the budget
    const int size = summary->block_size;
    const int block_cols = int((int64_t(frame_.cols) + size - 1) / size);
    uint32_t longest = 0;
    bool compact = true;
    for (const sbrt::BlockSummary &b : summary->blocks) {
        longest = std::max(longest, b.longest_stack);
        compact = compact && b.compact;
    }
    const unsigned count_bytes = sbrt::StackIndex::count_width(longest);
    const unsigned record_bytes = compact ? 4 : 8;
    uint64_t band_cells = 0, band_intervals = 0;
    band_rows_.push_back(0);
    for (int first = 0, k = 0; first < frame_.rows; first += size, ++k) {
        const int rows = std::min(size, frame_.rows - first);
        uint64_t intervals = 0;
        for (int c = 0; c < block_cols; ++c)
            intervals += summary->blocks[size_t(k) * size_t(block_cols) + size_t(c)].intervals;
        const uint64_t cells = uint64_t(rows) * uint64_t(frame_.cols);
        const uint64_t alone = band_bytes(cells, intervals, count_bytes, record_bytes);
        if (alone > memory_)
            sbrt::fail("SBRT <", name, ">: rows ", first, " to ", first + rows - 1,
                       " (one row of its blocks) need ", (alone + MB - 1) / MB,
                       " MB, more than memory=", memory_ / MB, ": give memory= at least that");
        if (band_cells && band_bytes(band_cells + cells, band_intervals + intervals,
                                     count_bytes, record_bytes) > std::min(memory_, BAND_BYTES)) {
            band_rows_.push_back(first);
            band_cells = band_intervals = 0;
        }
        band_cells += cells;
        band_intervals += intervals;
    }
    band_rows_.push_back(frame_.rows);
}

const sbrt::Model &SbrtBands::band_at(int row)
{
    if (row >= band_first_ && row < band_end_)
        return band_;
    if (row < band_end_)
        sbrt::fail("SbrtBands: row ", row, " asked for after row ", band_end_ - 1,
                   " (rows must come in order)");
    band_ = sbrt::Model(); // released before the next is read
    sbrt::ReadOptions options;
    options.threads = threads_;
    options.area = area_;
    if (whole_) { // no budget: every row at once
        band_ = read_sbrt_map(name_.c_str(), options);
        band_first_ = 0;
        band_end_ = band_.frame().rows;
    }
    else {
        const auto next = std::upper_bound(band_rows_.begin(), band_rows_.end(), row);
        band_first_ = *(next - 1);
        band_end_ = *next;
        options.rows = sbrt::ReadOptions::Rows{band_first_, band_end_ - band_first_};
        options.memory_limit = memory_;
        try {
            band_ = read_sbrt_map(name_.c_str(), options);
        }
        catch (const sbrt::Error &e) {
            sbrt::fail(e.what(), " (rows ", band_first_, " to ", band_end_ - 1,
                       "; memory= sets the budget)");
        }
    }
    ++bands_read_;
    largest_ = std::max(largest_, band_.memory_bytes());
    return band_;
}

} // namespace sbrt_grass
