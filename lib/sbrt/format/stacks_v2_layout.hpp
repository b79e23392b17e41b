/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The layout of a format 2 `stacks` file that its writer and
 *            its readers share: the header, the grid of blocks and the
 *            block table, opened and checked without decoding any block
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_STACKS_V2_LAYOUT_HPP
#define SBRT_STACKS_V2_LAYOUT_HPP

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "format/format_v2.hpp"

namespace sbrt {

constexpr uint8_t COMPRESSION_ZSTD = 1;
constexpr size_t BLOCK_ENTRY_BYTES = 24;
constexpr uint32_t MAX_BLOCK_SIZE = 4096;

/// \brief The blocks of a grid: square tiles of cells, row by row.
struct BlockGrid {
    int rows, cols, size;
    // in 64 bits: rows + size - 1 may pass INT32_MAX
    int block_rows() const { return int((int64_t(rows) + size - 1) / size); }
    int block_cols() const { return int((int64_t(cols) + size - 1) / size); }
    /// At most rows * cols <= 2^31 - 1 (Frame::validate).
    int count() const { return int(int64_t(block_rows()) * block_cols()); }
    int first_row(int block) const { return block / block_cols() * size; }
    int first_col(int block) const { return block % block_cols() * size; }
    int height(int block) const { return std::min(size, rows - first_row(block)); }
    int width(int block) const { return std::min(size, cols - first_col(block)); }
    uint64_t cells(int block) const { return uint64_t(height(block)) * uint64_t(width(block)); }
    /// Calls visit(cell) for the cells of `block` (indices row by row of
    /// the whole grid), in the order the block stores them.
    template <typename Visit>
    void for_each_cell(int block, const Visit &visit) const
    {
        const int r0 = first_row(block), c0 = first_col(block);
        for (int r = r0; r < r0 + height(block); ++r)
            for (int c = c0; c < c0 + width(block); ++c)
                visit(uint64_t(r) * uint64_t(cols) + uint64_t(c));
    }
};

/// \brief One block as stored in the block table.
struct BlockEntry {
    uint64_t offset = 0;
    uint32_t compressed = 0, raw = 0, intervals = 0, crc = 0;
};

/// Uncompressed bytes of a block of `cells` cells and `intervals` intervals.
uint64_t raw_block_size(const StacksV2Widths &w, uint64_t cells, uint64_t intervals);

/// \brief The fields of a v2 header that a reader needs.
struct HeaderV2 {
    uint16_t minor = FORMAT_V2_MINOR;
    uint32_t header_size = STACKS_V2_HEADER_SIZE;
    uint32_t required = 0, optional = 0;
    Frame frame;
    uint32_t materials = 0;
    uint64_t intervals = 0;
    uint32_t block_size = 0;
    StacksV2Widths widths;
    uint8_t compression = COMPRESSION_ZSTD;
    uint64_t materials_at = 0, table_at = 0, end = 0;
    uint32_t crc_materials = 0, crc_table = 0;
};

/// The 2.0 header's bytes (STACKS_V2_HEADER_SIZE, checksum last).
std::vector<uint8_t> encode_header_v2(const HeaderV2 &header);

/// \brief What opening a v2 file gives before any block is read: the
/// header, materials, grid and block table, all checked.
struct StacksV2Layout {
    HeaderV2 header;
    std::vector<Material> materials;
    BlockGrid grid{1, 1, 1};
    std::vector<BlockEntry> entries;
    uint64_t materials_end = 0; ///< where the blocks may begin
    /// Where the 2.1 block summaries begin (they end at the table); 0
    /// where the file has none.
    uint64_t summary_at = 0;
};

/// Opens untrusted bytes of a v2 file: the header (read by prefix: the
/// fields of 2.0, what a later minor version adds skipped), the section
/// offsets and counts, the checksums of header, materials and block table,
/// every table entry's place and size, and (2.1) the block summaries'
/// place, size and checksum, so that no byte of the file goes unchecked;
/// throws sbrt::Error naming `what`.
StacksV2Layout open_stacks_v2(const uint8_t *data, size_t size, const std::string &what);

} // namespace sbrt

#endif
