/****************************************************************************
 * MODULE:    lib/grass_sbrt (r3.sbrt addon)
 * PURPOSE:   An SBRT read for the columns under map points
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "column_reading.hpp"

#include <algorithm>
#include <optional>

#include "grass.hpp"
#include "module_errors.hpp"
#include "sbrt_store.hpp"
#include "format/paged_stacks.hpp"
#include "util/available_memory.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt_grass {

namespace {

/// The paged model of SBRT `name`, or nothing where it is older than
/// format 2.1 or has property channels (they lie along whole columns).
std::optional<sbrt::Model> read_paged_columns(const char *name, const ColumnReading &reading)
{
    const std::optional<sbrt::ModelSummary> summary = read_sbrt_summary_map(name);
    if (!summary || summary->has_channels)
        return std::nullopt;
    sbrt::Paging paging;
    paging.budget_bytes = reading.memory_bytes;
    paging.threads = reading.threads;
    // single columns need no ranges (no skipping, no framing); a map of
    // tops (a profile's location map) reads them where they are stored
    paging.column_ranges = reading.tops_map ? sbrt::Paging::Ranges::where_stored
                                            : sbrt::Paging::Ranges::none;
    paging.reserved_bytes = reserved_beside_blocks(*summary, reading.threads);
    try {
        sbrt::block_budget(*summary, paging);
    }
    catch (const sbrt::Error &e) {
        fail_with(_("SBRT <%s>: %s"), name, e.what());
    }
    if (reading.blocks_in_order) // a block a thread held: the one read
        paging.budget_bytes = std::min(
            paging.budget_bytes,
            sbrt::least_budget(*summary, paging) +
                sbrt::room_for_blocks(sbrt::thread_count(reading.threads) *
                                      summary->largest_decoded_block()));
    std::optional<sbrt::Model> model = read_sbrt_paged_map(name, paging);
    if (model)
        G_verbose_message(_("SBRT <%s> paged: its %d blocks decoded as their columns are "
                            "read, at most %.0f MB held with this process (memory=)"),
                          name, model->pages()->block_count(),
                          double(reading.memory_bytes) / (1 << 20));
    return model;
}

} // namespace

uint64_t reserved_beside_blocks(const sbrt::ModelSummary &summary, unsigned threads)
{
    return uint64_t(sbrt::resident_memory()) +
           sbrt::thread_count(threads) * summary.largest_decoded_block();
}

sbrt::Model read_sbrt_columns(const char *name, const std::vector<std::array<double, 2>> &points,
                              const ColumnReading &reading)
{
    if (std::optional<sbrt::Model> model = read_paged_columns(name, reading))
        return std::move(*model);
    sbrt::ReadOptions options;
    options.threads = reading.threads;
    options.points = points;
    sbrt::ReadReport report;
    options.report = &report;
    sbrt::Model model = read_sbrt_map(name, options);
    if (report.blocks)
        G_verbose_message(_("Read %llu of the %llu blocks of SBRT <%s>"),
                          (unsigned long long)report.blocks_read,
                          (unsigned long long)report.blocks, name);
    return model;
}

void report_paging(const sbrt::Model &model)
{
    if (const sbrt::StackPages *pages = model.pages()) {
        const sbrt::PagingFigures f = pages->figures();
        G_verbose_message(_("Paged model: %llu of the %d blocks decoded (again where "
                            "dropped), at most %.1f MB of them held at once"),
                          (unsigned long long)f.decodes, pages->block_count(),
                          double(f.peak_bytes) / (1 << 20));
    }
}

} // namespace sbrt_grass
