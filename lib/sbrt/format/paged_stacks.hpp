/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   A format 2.1 `stacks` file opened as a paged model: header,
 *            materials and block summaries read, each block decoded when a
 *            reader reaches it, within a memory budget (issue 49)
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_PAGED_STACKS_HPP
#define SBRT_PAGED_STACKS_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "format/block_summary.hpp"
#include "format/stacks_v2_layout.hpp"
#include "model/model.hpp"
#include "model/z_range.hpp"

namespace sbrt {

class MappedFile;

/// \brief How a paged model holds its blocks.
struct Paging {
    /// the most the model takes: decoded blocks, each column's range and
    /// the empty-space pyramid over them, and `reserved_bytes`
    uint64_t budget_bytes = 0;
    /// of the budget, what the caller holds beside the model (the process
    /// itself, its images, blocks dropped while a thread still reads
    /// them): not for blocks
    uint64_t reserved_bytes = 0;
    const char *budget_name = "memory="; ///< the option that sets it, for errors
    unsigned threads = 0;               ///< of the first pass; 0: all cores
    /// \brief Which column ranges a paged model holds.
    enum class Ranges {
        /// the tracer's (skipping, framing; the empty-space pyramid's
        /// level 0): stored, else read from every block
        needed,
        where_stored, ///< where a member holds them (a map of tops drawn cheaply), else none
        none,         ///< a reader of single columns (a virtual borehole)
    };
    Ranges column_ranges = Ranges::needed;
};

/// Bytes a column's range of the model of `summary` takes held
/// (ColumnRangeArray): 4 for a voxel model, else 8.
uint64_t column_range_bytes(const ModelSummary &summary);
/// Bytes of a paged model's column ranges (`range_bytes` each) and the
/// empty-space pyramid over them (its level 0 is they: MinMaxPyramid)
/// over `frame`, what its budget holds beside the blocks.
uint64_t skipping_bytes(const Frame &frame, uint64_t range_bytes = sizeof(ZRange));
/// The bytes left for decoded blocks where the budget of `paging` holds
/// the model's column ranges and pyramid (where read) and the reserved
/// bytes too;
/// throws sbrt::Error, saying what to give, where that leaves less than
/// its largest block decoded.
uint64_t block_budget(const ModelSummary &summary, const Paging &paging);
/// The part of a budget that holds `blocks` bytes of decoded blocks: an
/// eighth of what is left for blocks goes to the heap (glibc keeps the
/// memory of dropped blocks for the next).
uint64_t room_for_blocks(uint64_t blocks);
/// The least budget `paging` could have for the model of `summary`: its
/// column ranges (and pyramid), the reserved bytes and the room for its
/// largest block.
uint64_t least_budget(const ModelSummary &summary, const Paging &paging);

/// Whether a paged model of `summary` holds each column's top interval
/// (`tops_bytes` of them; 0: none stored) within the budget of `paging`:
/// where they take at most three quarters of what the budget leaves
/// beside what it needs at least (least_budget); the blocks keep the rest.
bool tops_fit(const ModelSummary &summary, const Paging &paging, uint64_t tops_bytes);

/// Block `block` of the opened file `data`, decompressed, its checksum,
/// counts and stacks checked (throws sbrt::Error naming `what`).
StackBlock decode_stack_block(const uint8_t *data, const StacksV2Layout &layout, int block,
                              const std::string &what);

/// \brief The bytes of one member of an SBRT, where it has it.
struct StoredMember {
    const std::vector<uint8_t> *bytes = nullptr;
    std::string what; ///< the member's name in errors
};

/// \brief The SBRT's `ranges` and `tops` members, where it has them.
struct StoredRanges {
    StoredMember ranges, tops;
};

/// The paged model of untrusted stacks bytes that `keep` holds in memory:
/// nothing where they are not format 2.1 with block summaries (decode
/// them whole instead). Each column's range of material (for the
/// empty-space pyramid and the framing) is read from `stored` where it
/// was made from these stacks (a damaged member throws), else from every
/// block once on opening; blocks stay held within the budget.
/// `mapping`, where given, is the file mapping `data` lies in (`keep`
/// holds it): each block's bytes leave the process's resident memory once
/// decoded (MappedFile::release).
std::optional<Model> open_paged_model(const uint8_t *data, size_t size,
                                      const std::string &what,
                                      std::shared_ptr<const void> keep, const Paging &paging,
                                      const StoredRanges &stored = {},
                                      const MappedFile *mapping = nullptr);

} // namespace sbrt

#endif
