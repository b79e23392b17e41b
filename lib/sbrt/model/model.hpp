/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   The stack-based representation of terrains (SBRT): grid frame,
 *            stacks of (material, top) intervals, material table
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_MODEL_HPP
#define SBRT_MODEL_HPP

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/interval_array.hpp"
#include "model/stack_index.hpp"
#include "model/stack_pages.hpp"

namespace sbrt {

/// Class id that stands for "no value" (GRASS's CELL null is INT_MIN too).
constexpr int32_t NULL_CLASS = std::numeric_limits<int32_t>::min();
/// Material index 0 is the reserved EMPTY material (air, caves, nulls).
constexpr uint32_t EMPTY = 0;
/// Largest number of materials, EMPTY included (keeps a material in 16 bits).
constexpr uint32_t MAX_MATERIALS = 65536;

/// \brief Georeferenced frame: the 2D grid plus the vertical frame.
/// Row 0 is the northernmost row (GRASS order); depth 0 the bottom slice.
struct Frame {
    double north = 1, south = 0, east = 1, west = 0;
    double bottom = 0, top = 1;
    int rows = 1, cols = 1, depths = 1;
    int proj = 0, zone = 0;

    double ns_res() const { return (north - south) / rows; }
    double ew_res() const { return (east - west) / cols; }
    double tb_res() const { return (top - bottom) / depths; }
    uint64_t cells() const { return uint64_t(rows) * uint64_t(cols); }
    uint64_t voxels() const { return cells() * uint64_t(depths); }
    /// Local height (units of tb_res above the bottom) of map elevation z.
    double local_z(double z) const { return (z - bottom) / tb_res(); }
    /// Throws sbrt::Error unless the frame is finite and non-degenerate.
    void validate(const char *where) const;
};

/// \brief A cell of the frame's 2D grid: row 0 is the northernmost.
struct GridCell {
    int row = 0, col = 0;
};

/// \brief The cell that holds map point (x, y), or nothing where the point
/// lies outside the frame or is not finite. Cells hold their west and
/// north edges, as GRASS's Rast_easting_to_col / Rast_northing_to_row and
/// r.what count them: a point on the frame's east or south edge is outside.
std::optional<GridCell> cell_of_point(const Frame &frame, double x, double y);

/// \brief A class of the source map with its legend.
struct Material {
    int32_t id = NULL_CLASS;
    std::string label;
    uint8_t red = 128, green = 128, blue = 128;
    bool has_color = false;
};

/// \brief Figures of the papers' memory comparison (Table 1).
struct Stats {
    uint64_t voxels = 0;
    uint64_t voxel_bytes = 0; ///< 4 bytes per voxel (FCELL), as in Table 1
    uint64_t sbrt_bytes = 0;  ///< index + intervals + materials, in memory
    uint64_t index_bytes = 0;    ///< of them the stack index
    uint64_t interval_bytes = 0; ///< and the intervals
    uint64_t intervals = 0;
    uint64_t solid_intervals = 0;
    uint32_t max_stack = 0;
    double mean_stack = 0;
    double compression_percent = 0;
};

/// The figures of Stats that follow from the frame and these counts (what
/// Model::stats() gives, and a stored summary without decoding):
/// `record_bytes` per interval, `index_bytes` of the stack index.
Stats stats_of(const Frame &frame, uint64_t intervals, uint64_t solid_intervals,
               uint32_t max_stack, uint64_t index_bytes, unsigned record_bytes,
               size_t materials);

/// \brief The whole model: frame, one stack per cell, materials.
class Model {
public:
    Model() = default;
    /// Takes ownership of the arrays; `offsets` has cells + 1 entries.
    /// Owned intervals are held compact where that is exact.
    Model(Frame frame, std::vector<Material> materials,
          const std::vector<uint32_t> &offsets, IntervalArray intervals);
    Model(Frame frame, std::vector<Material> materials, StackIndex index,
          IntervalArray intervals);
    /// A paged model: its stacks decoded block by block as they are read
    /// through `pages` (StackPin), `stats` those of the whole model. Its
    /// index() and intervals() are empty: code that reads every stack
    /// that way asks for a decoded model (is_paged()).
    Model(Frame frame, std::vector<Material> materials,
          std::shared_ptr<const StackPages> pages, Stats stats);

    const Frame &frame() const { return frame_; }
    const std::vector<Material> &materials() const { return materials_; }
    std::vector<Material> &materials() { return materials_; }
    /// The index and the intervals of a model decoded whole: a paged
    /// model's throw sbrt::Error (read its blocks through pages()).
    const StackIndex &index() const { return whole(), index_; }
    const IntervalArray &intervals() const { return whole(), intervals_; }
    /// The blocks of a paged model; null where the model is decoded whole.
    const StackPages *pages() const { return pages_.get(); }
    /// The same, shared (who keeps what it decoded on a GPU knows it by this).
    const std::shared_ptr<const StackPages> &shared_pages() const { return pages_; }
    bool is_paged() const { return pages_ != nullptr; }

    uint64_t cell_index(int row, int col) const
    {
        return uint64_t(row) * uint64_t(frame_.cols) + uint64_t(col);
    }
    StackRange stack(uint64_t cell) const { return whole(), index_.range(cell); }
    uint64_t stack_begin(uint64_t cell) const { return stack(cell).begin; }
    uint64_t stack_end(uint64_t cell) const { return stack(cell).end; }
    uint32_t stack_size(uint64_t cell) const { return whole(), index_.size(cell); }
    /// visit(first, last) over the records of the stack of `cell` (bottom
    /// up, typed as held), its result returned: a model decoded whole, or
    /// a paged one (its block decoded where it is not held; code that is
    /// not hot, where a pin per block is not worth keeping).
    template <typename Visit>
    auto visit_stack(uint64_t cell, const Visit &visit) const
    {
        if (pages_) {
            const int row = int(cell / uint64_t(frame_.cols));
            const int col = int(cell % uint64_t(frame_.cols));
            const std::shared_ptr<const StackBlock> block =
                pages_->block(pages_->block_of(row, col));
            const StackRange s = block->range(row, col);
            return block->intervals.visit(
                [&](const auto *records) { return visit(records + s.begin, records + s.end); });
        }
        const StackRange s = index_.range(cell);
        return intervals_.visit(
            [&](const auto *records) { return visit(records + s.begin, records + s.end); });
    }
    /// The top (local height) of the stack of `cell`, or a negative number
    /// where it is empty (no stack ends EMPTY): a paged model's stored
    /// column ranges say it without decoding, where it holds them.
    double stack_top(uint64_t cell) const
    {
        if (pages_ && pages_->has_column_ranges()) {
            const ZRange range = pages_->column_ranges()[cell];
            return range.empty() ? -1.0 : double(range.high);
        }
        return visit_stack(cell, [](const auto *first, const auto *last) {
            return first != last ? double((last - 1)->top) : -1.0;
        });
    }
    /// The intervals of one stack, widened (for code that is not hot).
    std::vector<Interval> stack_intervals(uint64_t cell) const;
    /// Bytes the index and the intervals take in memory (a paged model:
    /// the blocks held now).
    uint64_t memory_bytes() const
    {
        return pages_ ? pages_->figures().held_bytes
                      : index_.bytes() + intervals_.size() * intervals_.record_bytes();
    }
    /// The vertical datum heights are relative to ("NAP"), where the
    /// source named one; empty where unknown.
    const std::string &vertical_datum() const { return vertical_datum_; }
    void set_vertical_datum(std::string datum) { vertical_datum_ = std::move(datum); }
    /// Material index whose class id is `id`, or -1.
    int64_t find_material(int32_t id) const;

    Stats stats() const;
    /// Checks every invariant (sorted tops, merged runs, no trailing EMPTY,
    /// indices in range); throws sbrt::Error listing the problems found.
    /// A paged model's blocks are checked as they are decoded.
    void validate() const;

private:
    /// Throws where the model is paged (its stacks are not held whole).
    void whole() const
    {
        if (pages_)
            fail_paged();
    }
    [[noreturn]] static void fail_paged();

    Frame frame_;
    std::vector<Material> materials_;
    StackIndex index_;
    IntervalArray intervals_;
    std::shared_ptr<const StackPages> pages_;
    Stats paged_stats_;
    std::string vertical_datum_;
};

/// Checks the stacks of `index` over `intervals` as Model::validate does
/// for a grid of `frame` (its depths bound the tops) and `material_count`
/// materials, on `threads` threads (0: all cores).
void validate_stacks(const Frame &frame, const StackIndex &index,
                     const IntervalArray &intervals, size_t material_count, unsigned threads);

} // namespace sbrt

#endif
