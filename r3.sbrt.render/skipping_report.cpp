/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   Verbose messages on what the scene skips
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "skipping_report.hpp"

#include "grass.hpp"

namespace {

unsigned long long ull(uint64_t n)
{
    return (unsigned long long)n;
}

void report_left_out(const char *why, const sbrt::Pruned &p)
{
    G_verbose_message(_("Skipped, %s: %llu stacks, %llu intervals, %llu bytes "
                        "(not traced or uploaded)"),
                      why, ull(p.cells), ull(p.intervals), ull(p.bytes));
}

} // namespace

void report_hidden(const sbrt::Model &read, const sbrt::Model &left, size_t hidden)
{
    const uint64_t removed = read.intervals().size() - left.intervals().size();
    uint64_t emptied = 0;
    for (uint64_t c = 0; c < read.frame().cells(); ++c)
        emptied += read.stack_size(c) && !left.stack_size(c);
    G_verbose_message(_("Skipped, %zu hidden strata: %llu intervals removed or "
                        "merged (%llu bytes), %llu stacks left empty"),
                      hidden, ull(removed), ull(removed * read.intervals().record_bytes()),
                      ull(emptied));
}

void report_hidden_while_tracing(size_t hidden)
{
    G_verbose_message(_("%zu hidden strata: crossed as air while tracing (the model as "
                        "read; the empty-space pyramid leaves them out)"),
                      hidden);
}

void report_pruning(const sbrt::Pruning &pruning, size_t planes)
{
    report_left_out(_("out of the view"), pruning.outside_view);
    if (planes)
        report_left_out(_("cut away by the planes"), pruning.cut_away);
}

void report_pyramid(const sbrt::MinMaxPyramid &p, const sbrt::Model &m)
{
    if (!p.levels() || G_verbose() <= G_verbose_std())
        return; // skipping off, or only overlays drawn; or not --verbose
                // (counting the empty cells walks the grid)
    // a paged model's, from its summaries (held decoded: only those reached)
    const uint64_t intervals = m.is_paged() ? m.stats().intervals : m.intervals().size();
    const uint64_t bytes = m.is_paged() ? m.stats().interval_bytes
                                        : intervals * m.intervals().record_bytes();
    G_verbose_message(_("Empty-space skipping: %d-level min-max pyramid (%llu "
                        "bytes); %llu of %llu cells hold nothing to draw; %zu "
                        "intervals (%llu bytes) left to trace"),
                      p.levels(), ull(p.bytes()), ull(p.empty_cells()),
                      ull(m.frame().cells()), size_t(intervals), ull(bytes));
}
