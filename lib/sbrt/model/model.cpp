/****************************************************************************
 * MODULE:    lib/sbrt (r3.sbrt addon)
 * PURPOSE:   SBRT model: invariants, look-ups and the memory figures
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "model/model.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt {

std::optional<GridCell> cell_of_point(const Frame &frame, double x, double y)
{
    if (!std::isfinite(x) || !std::isfinite(y))
        return std::nullopt;
    // floor, not truncation: points a fraction of a cell west or north of
    // the frame give -1, not 0
    const double col = std::floor((x - frame.west) / frame.ew_res());
    const double row = std::floor((frame.north - y) / frame.ns_res());
    if (col < 0 || col >= frame.cols || row < 0 || row >= frame.rows)
        return std::nullopt;
    return GridCell{int(row), int(col)};
}


void Frame::validate(const char *where) const
{
    const double values[] = {north, south, east, west, bottom, top};
    for (double v : values)
        if (!std::isfinite(v))
            fail(where, ": frame has a non-finite coordinate");
    if (rows < 1 || cols < 1 || depths < 1)
        fail(where, ": frame has no cells (rows=", rows, " cols=", cols,
             " depths=", depths, ")");
    if (!(north > south) || !(east > west) || !(top > bottom))
        fail(where, ": frame has an empty extent (n=", north, " s=", south,
             " e=", east, " w=", west, " t=", top, " b=", bottom, ")");
    if (cells() > uint64_t(std::numeric_limits<int32_t>::max()))
        fail(where, ": too many cells (", cells(), "), at most 2^31-1");
    if (depths > (1 << 24))
        fail(where, ": too many depths (", depths,
             "), at most 2^24 keeps voxel heights exact in float32");
}

namespace {

/// The stack index of cells + 1 offsets.
StackIndex index_of(const std::vector<uint32_t> &offsets, const Frame &frame)
{
    if (offsets.size() != frame.cells() + 1)
        fail("SBRT model: index has ", offsets.size(), " entries, expected ",
             frame.cells() + 1);
    return StackIndex::from_offsets(offsets.data(), frame.cells());
}

} // namespace

Model::Model(Frame frame, std::vector<Material> materials,
             const std::vector<uint32_t> &offsets, IntervalArray intervals)
    : Model(frame, std::move(materials), index_of(offsets, frame), std::move(intervals))
{
}

Model::Model(Frame frame, std::vector<Material> materials, StackIndex index,
             IntervalArray intervals)
    : frame_(frame), materials_(std::move(materials)), index_(std::move(index)),
      intervals_(std::move(intervals).packed())
{
}

Model::Model(Frame frame, std::vector<Material> materials,
             std::shared_ptr<const StackPages> pages, Stats stats)
    : frame_(frame), materials_(std::move(materials)), pages_(std::move(pages)),
      paged_stats_(stats)
{
    if (!pages_ || pages_->rows() != frame_.rows || pages_->cols() != frame_.cols)
        fail("Model: pages of another grid than ", frame_.rows, " x ", frame_.cols);
}

void Model::fail_paged()
{
    fail("this reads every stack of the model, which is paged (its blocks decoded as "
         "rays reach them); it needs the model decoded whole");
}

std::vector<Interval> Model::stack_intervals(uint64_t cell) const
{
    return visit_stack(cell, [](const auto *first, const auto *last) {
        std::vector<Interval> out;
        out.reserve(size_t(last - first));
        for (const auto *r = first; r != last; ++r)
            out.push_back({r->material, float(r->top)});
        return out;
    });
}

int64_t Model::find_material(int32_t id) const
{
    for (size_t i = 1; i < materials_.size(); ++i)
        if (materials_[i].id == id)
            return int64_t(i);
    return -1;
}

Stats stats_of(const Frame &frame, uint64_t intervals, uint64_t solid_intervals,
               uint32_t max_stack, uint64_t index_bytes, unsigned record_bytes,
               size_t materials)
{
    Stats s;
    s.voxels = frame.voxels();
    s.voxel_bytes = s.voxels * 4;
    s.intervals = intervals;
    s.solid_intervals = solid_intervals;
    s.index_bytes = index_bytes;
    s.interval_bytes = intervals * record_bytes;
    s.sbrt_bytes = s.index_bytes + s.interval_bytes + materials * 8;
    s.max_stack = max_stack;
    s.mean_stack = frame.cells() ? double(intervals) / frame.cells() : 0;
    s.compression_percent =
        s.voxel_bytes ? 100.0 * (1.0 - double(s.sbrt_bytes) / s.voxel_bytes) : 0;
    return s;
}

Stats Model::stats() const
{
    if (pages_)
        return paged_stats_;
    uint64_t solid = 0;
    intervals_.visit([&](const auto *records) {
        for (size_t i = 0; i < intervals_.size(); ++i)
            solid += records[i].material != EMPTY;
    });
    return stats_of(frame_, intervals_.size(), solid, index_.max_size(), index_.bytes(),
                    intervals_.record_bytes(), materials_.size());
}

namespace {

/// Whether a stack keeps every invariant: material indices in range, tops
/// rising within the depths, no two adjacent intervals of one material,
/// no trailing EMPTY. Branch-free over the intervals (the hot path of
/// every model read); list_stack_problems says what is wrong.
template <typename Record>
bool stack_is_sound(const Record *first, const Record *last, uint32_t materials,
                    float depth_limit)
{
    float below = 0;
    uint32_t previous = UINT32_MAX;
    bool bad = false;
    for (const Record *r = first; r != last; ++r) {
        const uint32_t material = r->material;
        const float top = float(r->top);
        bad |= material >= materials;
        bad |= !(top > below) || !(top <= depth_limit);
        bad |= material == previous;
        below = top;
        previous = material;
    }
    return !bad && previous != EMPTY;
}

/// Each broken invariant of the stack of `cell`, in words, to `add`.
template <typename Record, typename Add>
void list_stack_problems(uint64_t cell, const Record *first, const Record *last,
                         uint32_t materials, float depth_limit, const Add &add)
{
    const std::string at = "cell " + std::to_string(cell);
    float below = 0;
    uint32_t previous = UINT32_MAX;
    for (const Record *r = first; r != last; ++r) {
        const uint32_t material = r->material;
        const float top = float(r->top);
        if (material >= materials)
            add(at + ": material index " + std::to_string(material) + " out of range");
        if (!(top > below) || !(top <= depth_limit))
            add(at + ": interval top " + std::to_string(top) + " not in (" +
                std::to_string(below) + ", " + std::to_string(depth_limit) + "]");
        if (material == previous)
            add(at + ": adjacent intervals of one material");
        below = top;
        previous = material;
    }
    if (previous == EMPTY)
        add(at + ": trailing EMPTY interval");
}

} // namespace

void Model::validate() const
{
    frame_.validate("SBRT model");
    if (!pages_)
        validate_stacks(frame_, index_, intervals_, materials_.size(), 0);
}

void validate_stacks(const Frame &frame, const StackIndex &index,
                     const IntervalArray &intervals, size_t material_count, unsigned threads)
{
    if (index.cells() != frame.cells())
        fail("SBRT model: index has ", index.cells(), " cells, expected ",
             frame.cells());
    if (index.total() != intervals.size())
        fail("SBRT model: index does not span the ", intervals.size(),
             " intervals");
    // the problems of each run of cells, on all cores; the first few (in
    // cell order) are listed
    constexpr int LISTED = 8;
    struct Problems {
        int count = 0;
        std::vector<std::string> first;
        void add(const std::string &text)
        {
            if (count++ < LISTED)
                first.push_back(text);
        }
    };
    const uint64_t cells = frame.cells();
    // runs of 4096 cells or more: a small model (and the fuzzer's) on
    // this thread alone
    const int runs = int(std::min<uint64_t>(cells / 4096 + 1, 1024));
    std::vector<Problems> found(size_t(runs) + 1);
    if (material_count == 0 || material_count > MAX_MATERIALS)
        found[0].add("material count " + std::to_string(material_count) + " not in 1.." +
                     std::to_string(MAX_MATERIALS));
    const float depth_limit = float(frame.depths);
    intervals.visit([&](const auto *records) {
        for_each_row(runs, threads, [&](int run) {
            Problems &problems = found[size_t(run) + 1];
            const uint64_t first = cells * uint64_t(run) / uint64_t(runs);
            const uint64_t last = cells * uint64_t(run + 1) / uint64_t(runs);
            uint64_t i = index.range(first).begin;
            for (uint64_t c = first; c < last; ++c) {
                const uint64_t end = i + index.size(c);
                if (!stack_is_sound(records + i, records + end, uint32_t(material_count),
                                    depth_limit))
                    list_stack_problems(c, records + i, records + end, uint32_t(material_count),
                                        depth_limit, [&](const std::string &text) {
                                            problems.add(text);
                                        });
                i = end;
            }
        });
    });
    int count = 0, shown = 0;
    std::ostringstream listed;
    for (const Problems &problems : found) {
        count += problems.count;
        for (const std::string &text : problems.first)
            if (shown++ < LISTED)
                listed << "\n  " << text;
    }
    if (count)
        fail("SBRT model: ", count, " problem(s):", listed.str());
}

} // namespace sbrt
