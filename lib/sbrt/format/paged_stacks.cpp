/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A format 2.1 `stacks` file opened as a paged model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/paged_stacks.hpp"

#include <string>

#include "format/column_ranges_file.hpp"
#include "format/column_tops_file.hpp"

#include "format/block_summary.hpp"
#include "format/mapped_file.hpp"
#include "format/stacks_fields.hpp"

namespace sbrt {

uint64_t column_range_bytes(const ModelSummary &summary)
{
    // a voxel model's ranges are pairs of voxel boundaries: u16 pairs
    // (its ranges member is narrow below 65535, as the writer makes it,
    // and ranges read from its blocks are read so)
    return summary.tops == TopEncoding::VoxelBoundaries && summary.frame.depths < UINT16_MAX
               ? sizeof(CompactRange)
               : sizeof(ZRange);
}

uint64_t skipping_bytes(const Frame &frame, uint64_t range_bytes)
{
    // each column's range, the pyramid's level 0, and the levels above
    // it, a third as many nodes of two floats (hidden strata and cut
    // cells narrow only those)
    return frame.cells() * range_bytes + frame.cells() * sizeof(ZRange) / 3;
}

namespace {

/// Of what the budget leaves for blocks, one part in HEAP_SHARE is left to
/// the heap: the memory of dropped blocks that glibc keeps in its arenas
/// for the next ones rather than returning it (a national view's resident
/// memory passed its blocks' share by an eighth without it).
constexpr uint64_t HEAP_SHARE = 8;

/// Bytes of the column ranges `paging` holds: the ranges and the pyramid
/// over them; the ranges alone where stored; none.
uint64_t ranges_bytes(const ModelSummary &summary, const Paging &paging)
{
    switch (paging.column_ranges) {
    case Paging::Ranges::needed:
        return skipping_bytes(summary.frame, column_range_bytes(summary));
    case Paging::Ranges::where_stored:
        return summary.frame.cells() * column_range_bytes(summary);
    case Paging::Ranges::none:
        break;
    }
    return 0;
}

} // namespace

uint64_t room_for_blocks(uint64_t blocks)
{
    return blocks + (blocks + HEAP_SHARE - 2) / (HEAP_SHARE - 1);
}

uint64_t least_budget(const ModelSummary &summary, const Paging &paging)
{
    return ranges_bytes(summary, paging) + paging.reserved_bytes +
           room_for_blocks(summary.largest_decoded_block());
}

bool tops_fit(const ModelSummary &summary, const Paging &paging, uint64_t tops_bytes)
{
    const uint64_t least = least_budget(summary, paging);
    // a block's top intervals take a fifteenth of the block decoded (a
    // national GeoTOP-like block: 16 KB against 240 KB) and answer most
    // rays of a view from above, so they take up to three quarters of the
    // room: the 16x model's default view with memory=2000 then decodes 297
    // blocks instead of 7,387
    return tops_bytes > 0 && paging.budget_bytes > least &&
           tops_bytes <= (paging.budget_bytes - least) / 4 * 3;
}

uint64_t block_budget(const ModelSummary &summary, const Paging &paging)
{
    const uint64_t ranges = ranges_bytes(summary, paging);
    const uint64_t block = summary.largest_decoded_block();
    const uint64_t least = least_budget(summary, paging);
    if (paging.budget_bytes < least) {
        const auto mb = [](uint64_t bytes) { return (bytes >> 20) + 1; };
        const char *ranges_are = paging.column_ranges != Paging::Ranges::where_stored
                                     ? "each column's range and the empty-space pyramid over "
                                       "them, "
                                     : "each column's range, ";
        fail("a memory budget (", paging.budget_name, ") of ", paging.budget_bytes >> 20,
             " MB is less than the ", mb(least), " MB this model needs at least (",
             ranges ? ranges_are : "", ranges ? std::to_string(mb(ranges)) + " MB; " : "",
             "its largest block decoded and the heap's share, ", mb(room_for_blocks(block)),
             " MB",
             paging.reserved_bytes ? "; the rest of this process (its code, buffers and a "
                                     "block for each thread), "
                                   : "",
             paging.reserved_bytes ? std::to_string(mb(paging.reserved_bytes)) + " MB" : "",
             "): give ", paging.budget_name, " at least ", mb(least));
    }
    const uint64_t room = paging.budget_bytes - ranges - paging.reserved_bytes;
    return room - room / HEAP_SHARE;
}

std::optional<Model> open_paged_model(const uint8_t *data, size_t size,
                                      const std::string &what,
                                      std::shared_ptr<const void> keep, const Paging &paging,
                                      const StoredRanges &stored, const MappedFile *mapping)
{
    if (stacks_major_version(data, size) != FORMAT_V2_MAJOR)
        return std::nullopt;
    auto layout = std::make_shared<const StacksV2Layout>(open_stacks_v2(data, size, what));
    // each column's range, where a member made from these stacks holds it
    ColumnRangeArray ranges;
    if (stored.ranges.bytes && paging.column_ranges != Paging::Ranges::none)
        if (auto decoded = decode_column_ranges(stored.ranges.bytes->data(),
                                                stored.ranges.bytes->size(), stored.ranges.what,
                                                layout->header.frame,
                                                stamp_of(layout->header), paging.threads))
            ranges = std::move(*decoded);
    std::optional<ModelSummary> summary = read_stacks_summary(data, size, what);
    if (!summary)
        return std::nullopt;
    // each column's top interval, for the tracer, where stored and its
    // budget has room for it beside the blocks
    std::optional<IntervalArray> tops;
    Paging with_tops = paging;
    const StoredMember &stored_tops = stored.tops;
    if (!ranges.empty() && stored_tops.bytes && paging.column_ranges == Paging::Ranges::needed &&
        tops_fit(*summary, paging,
                 column_tops_bytes(stored_tops.bytes->data(), stored_tops.bytes->size(),
                                   summary->frame, stored_tops.what)))
        tops = decode_column_tops(stored_tops.bytes->data(), stored_tops.bytes->size(),
                                  stored_tops.what,
                                  summary->frame, stamp_of(layout->header), ranges,
                                  summary->materials.size(), paging.threads);
    if (tops)
        with_tops.reserved_bytes += uint64_t(tops->size()) * tops->record_bytes();
    // (a member of floats all of whose ranges are voxel boundaries, which
    // no writer makes: the bytes the budget did not count on)
    const uint64_t range_bytes = column_range_bytes(*summary);
    if (!ranges.empty() && ranges.record_bytes() > range_bytes)
        with_tops.reserved_bytes += uint64_t(ranges.size()) * (ranges.record_bytes() - range_bytes);
    const uint64_t blocks_budget = block_budget(*summary, with_tops);
    auto decode = [data, layout, what, mapping, keep = std::move(keep)](int block) {
        StackBlock decoded = decode_stack_block(data, *layout, block, what);
        // its compressed bytes leave the process's memory (the page cache
        // keeps them): a view of many blocks holds its budget
        const BlockEntry &entry = layout->entries[size_t(block)];
        if (mapping)
            mapping->release(data + entry.offset, entry.compressed);
        return decoded;
    };
    auto pages = std::make_shared<StackPages>(summary->frame, int(layout->grid.size),
                                              std::move(decode), blocks_budget,
                                              paging.budget_name, paging.threads,
                                              std::move(ranges),
                                              paging.column_ranges == Paging::Ranges::needed,
                                              range_bytes == sizeof(CompactRange));
    // each block's classes: hiding one prepares only the blocks that hold it
    std::vector<std::vector<uint16_t>> materials;
    for (BlockSummary &block : summary->blocks)
        materials.push_back(std::move(block.materials));
    pages->set_block_materials(std::move(materials));
    if (tops)
        pages->set_column_tops(std::move(*tops));
    return Model(summary->frame, std::move(summary->materials), std::move(pages),
                 summary->stats);
}

} // namespace sbrt
