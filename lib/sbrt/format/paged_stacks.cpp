/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A format 2.1 `stacks` file opened as a paged model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "format/paged_stacks.hpp"

#include <string>

#include "format/column_ranges_file.hpp"

#include "format/block_summary.hpp"
#include "format/stacks_fields.hpp"

namespace sbrt {

uint64_t skipping_bytes(const Frame &frame)
{
    // each column's range, and the pyramid over them (its levels add a
    // third to its first)
    return frame.cells() * sizeof(ZRange) * 7 / 3;
}

uint64_t block_budget(const ModelSummary &summary, const Paging &paging)
{
    // the ranges and the pyramid over them; the ranges alone where
    // stored; nothing
    const uint64_t skipping =
        paging.column_ranges == Paging::Ranges::needed         ? skipping_bytes(summary.frame)
        : paging.column_ranges == Paging::Ranges::where_stored ? summary.frame.cells() *
                                                                     sizeof(ZRange)
                                                               : 0;
    const uint64_t block = summary.largest_decoded_block();
    const uint64_t held = skipping + paging.reserved_bytes;
    if (paging.budget_bytes < held + block) {
        const auto mb = [](uint64_t bytes) { return (bytes >> 20) + 1; };
        fail("a memory budget (", paging.budget_name, ") of ", paging.budget_bytes >> 20,
             " MB is less than the ", mb(held + block), " MB this model needs at least (",
             skipping ? "each column's range and the empty-space pyramid over them, " : "",
             skipping ? std::to_string(mb(skipping)) + " MB; " : "",
             "its largest block decoded, ", mb(block), " MB",
             paging.reserved_bytes ? "; this process beside the model, " : "",
             paging.reserved_bytes ? std::to_string(mb(paging.reserved_bytes)) + " MB" : "",
             "): give ", paging.budget_name, " at least ", mb(held + block));
    }
    return paging.budget_bytes - held;
}

std::optional<Model> open_paged_model(const uint8_t *data, size_t size,
                                      const std::string &what,
                                      std::shared_ptr<const void> keep, const Paging &paging,
                                      const StoredRanges &stored)
{
    if (stacks_major_version(data, size) != FORMAT_V2_MAJOR)
        return std::nullopt;
    auto layout = std::make_shared<const StacksV2Layout>(open_stacks_v2(data, size, what));
    // each column's range, where a member made from these stacks holds it
    std::vector<ZRange> ranges;
    if (stored.bytes && paging.column_ranges != Paging::Ranges::none)
        if (auto decoded = decode_column_ranges(stored.bytes->data(), stored.bytes->size(),
                                                stored.what, layout->header.frame,
                                                stamp_of(layout->header)))
            ranges = std::move(*decoded);
    std::optional<ModelSummary> summary = read_stacks_summary(data, size, what);
    if (!summary)
        return std::nullopt;
    const uint64_t blocks_budget = block_budget(*summary, paging);
    auto decode = [data, layout, what, keep = std::move(keep)](int block) {
        return decode_stack_block(data, *layout, block, what);
    };
    auto pages = std::make_shared<StackPages>(summary->frame, int(layout->grid.size),
                                              std::move(decode), blocks_budget,
                                              paging.budget_name, paging.threads,
                                              std::move(ranges),
                                              paging.column_ranges == Paging::Ranges::needed);
    // each block's classes: hiding one prepares only the blocks that hold it
    std::vector<std::vector<uint16_t>> materials;
    for (BlockSummary &block : summary->blocks)
        materials.push_back(std::move(block.materials));
    pages->set_block_materials(std::move(materials));
    return Model(summary->frame, std::move(summary->materials), std::move(pages),
                 summary->stats);
}

} // namespace sbrt
