/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The scene's data resident on the GPU
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_model.hpp"

#include <algorithm>
#include <vector>

#include "gpu_internal.hpp"
#include "gpu/gpu_layout.hpp"
#include "gpu/gpu_overlays.hpp"

namespace sbrt_gl {

namespace {

/// The largest width and height of a 2D texture.
int max_texture_side(const GlApi &gl)
{
    GLint side = 0;
    gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &side);
    return std::max(side, 1);
}

/// A storage buffer of `words`, named `what` where it exceeds `limit`.
template <class T>
GlBuffer storage_buffer(const GlApi &gl, const std::vector<T> &words, size_t limit,
                        const char *what)
{
    return GlBuffer(gl, GL_SHADER_STORAGE_BUFFER,
                    checked_bytes(words.size() * sizeof(T), limit, what), words.data());
}

/// An empty-space pyramid (binding 4), from `first_level` on.
GlBuffer pyramid_buffer(const GlApi &gl, const sbrt::MinMaxPyramid &pyramid, size_t limit,
                        int first_level = 0)
{
    checked_bytes(size_t(sbrt::gpu_pyramid_bytes(pyramid, first_level)), limit,
                  "empty-space pyramid");
    return storage_buffer(gl, sbrt::make_gpu_pyramid(pyramid, first_level), limit,
                          "empty-space pyramid");
}

uint64_t megabytes(uint64_t bytes) { return (bytes + (1 << 20) - 1) >> 20; }

/// The page table's bytes: its head, and a word a page.
uint64_t page_table_bytes(const sbrt::StackPages &pages, bool column_pages)
{
    return (uint64_t(sbrt::GPU_PAGE_TABLE_HEAD) +
            uint64_t(sbrt::gpu_page_count(pages, column_pages))) * 4;
}

/// Bytes of the columns' top intervals where they go up whole as the
/// shader reads them (`compact`: a word each), else 0.
uint64_t whole_tops_bytes(const sbrt::StackPages &pages, bool compact)
{
    const sbrt::IntervalArray &tops = pages.column_tops();
    if (!pages.has_column_tops() || tops.is_compact() != compact)
        return 0;
    return uint64_t(tops.size()) * tops.record_bytes();
}

/// The first level from which a paged model's pyramid goes up beside its
/// columns' pages: the first to take at most a quarter of `budget` (and
/// fit `limit`), or 0 where none does.
int first_level_beside_pages(const sbrt::MinMaxPyramid &pyramid, uint64_t budget, size_t limit)
{
    for (int level = 1; level < pyramid.levels(); ++level) {
        const uint64_t bytes = sbrt::gpu_pyramid_bytes(pyramid, level);
        if (bytes <= budget / 4 && bytes <= limit)
            return level;
    }
    return 0;
}

/// How a paged model's pyramid and columns go up within `budget` bytes
/// (GpuModel's comment); checked before a word is made: the pyramid of a
/// model 16 times national takes more than a gigabyte.
PagedPlan plan_paging(const sbrt::Tracer &tracer, const GpuOptions &options, size_t limit)
{
    if (options.layout != sbrt::GpuLayout::ssbo)
        sbrt::fail("a model read block by block goes to the GPU in layout=ssbo only");
    const sbrt::MinMaxPyramid &pyramid = tracer.pyramid();
    const sbrt::StackPages &pages = *tracer.model().pages();
    const uint64_t budget = options.page_budget_bytes;
    PagedPlan plan;
    plan.form.compact = compact_on_gpu(tracer.model());
    // (a pyramid of one level has none above the columns to climb)
    const bool pages_columns =
        pages.has_column_tops() && pages.has_column_ranges() && pyramid.levels() > 1;
    if (pages_columns && options.column_pages_from_level > 0) {
        plan.first_level = std::min(options.column_pages_from_level, pyramid.levels() - 1);
        plan.form.column_pages = true;
        return plan;
    }
    // level 0 as the model's column ranges (kept from scene to scene), the
    // scene's levels above; without the ranges, all in the pyramid
    const bool ranges = pages.has_column_ranges() && pyramid.levels() > 1;
    const uint64_t range_bytes = ranges ? uint64_t(pages.column_ranges().size()) * 8 : 0;
    const uint64_t above = sbrt::gpu_pyramid_bytes(pyramid, ranges ? 1 : 0);
    const bool fits = range_bytes + above <= budget / 2 && range_bytes <= limit && above <= limit;
    const uint64_t rest =
        budget - std::min(budget, range_bytes + above + page_table_bytes(pages, false));
    const uint64_t tops = whole_tops_bytes(pages, plan.form.compact);
    const bool tops_fit = tops > 0 && tops <= rest / 2 && tops <= limit;
    if (fits) { // (tops that do not fit stay on the host: rays read blocks)
        plan.first_level = ranges ? 1 : 0;
        plan.form.ranges_whole = ranges;
        plan.form.tops_whole = tops_fit;
        return plan;
    }
    if (pages_columns && (plan.first_level = first_level_beside_pages(pyramid, budget, limit))) {
        plan.form.column_pages = true;
        return plan;
    }
    sbrt::fail("the model's empty-space pyramid takes ", megabytes(range_bytes + above),
               " MB on the GPU, more than half of gpu_memory (", budget >> 20, " MB), ",
               pages.has_column_tops() ? "and its levels above the columns do not fit a quarter"
                                       : "and the model holds no column tops to page its columns",
               ": give more, or render with backend=cpu");
}

/// How each material looks (binding 3).
GlBuffer material_buffer(const GlApi &gl, const sbrt::Tracer &tracer)
{
    const std::vector<sbrt::GpuMaterial> table = sbrt::make_gpu_materials(tracer);
    return GlBuffer(gl, GL_SHADER_STORAGE_BUFFER,
                    table.size() * sizeof(sbrt::GpuMaterial), table.data());
}

} // namespace

GpuModel::GpuModel(const GlApi &gl, const sbrt::Tracer &tracer, const GpuOptions &options,
                   size_t max_block_bytes)
    : gl_(gl), tracer_(tracer), max_block_bytes_(max_block_bytes), layout_(options.layout),
      plan_(tracer.model().is_paged() ? plan_paging(tracer, options, max_block_bytes)
                                      : PagedPlan{}),
      materials_(material_buffer(gl, tracer)),
      pyramid_(pyramid_buffer(gl, tracer.pyramid(), max_block_bytes, plan_.first_level))
{
    const uint64_t page_budget_bytes = options.page_budget_bytes;
    std::shared_ptr<GpuPageAtlas> *kept_atlas = options.kept_atlas;
    if (&tracer.model_pyramid() != &tracer.pyramid())
        model_pyramid_.emplace(pyramid_buffer(gl_, tracer.model_pyramid(), max_block_bytes_));
    if (tracer.model().is_paged())
        open_pages(tracer.model(), page_budget_bytes, kept_atlas);
    else {
        memory_ = sbrt::gpu_memory(tracer.model(), layout_, max_texture_side(gl));
        upload_stacks(tracer.model());
    }
    gl_.Finish();
    check_gl(gl_, "uploading the model");
}

void GpuModel::open_pages(const sbrt::Model &model, uint64_t budget_bytes,
                          std::shared_ptr<GpuPageAtlas> *kept_atlas)
{
    if (sbrt::gpu_overlay_mode(tracer_) != sbrt::GpuOverlayMode::none)
        sbrt::fail("boreholes and fence panels on the GPU need the model read whole, "
                   "not block by block");
    // the pyramid, the page table and the columns held whole are a part of
    // the budget (boreholes, with a pyramid of their own, are not paged)
    const sbrt::StackPages &pages = *model.pages();
    const PagedForm &form = plan_.form;
    const uint64_t table_bytes = page_table_bytes(pages, form.column_pages);
    const uint64_t column_bytes =
        (form.ranges_whole ? uint64_t(pages.column_ranges().size()) * 8 : 0) +
        (form.tops_whole ? whole_tops_bytes(pages, form.compact) : 0);
    budget_bytes -= std::min<uint64_t>(budget_bytes, pyramid_.bytes() + table_bytes + column_bytes);
    if (atlas_words(budget_bytes, max_block_bytes_) == 0)
        sbrt::fail("gpu_memory leaves no room for the model's blocks beside its empty-space "
                   "pyramid and page table: give more, or render with backend=cpu");
    // the atlas of another scene of this model, its blocks up, where kept
    if (kept_atlas && *kept_atlas &&
        (*kept_atlas)->serves(pages, form, budget_bytes, max_block_bytes_))
        pages_ = *kept_atlas;
    else
        pages_ = std::make_shared<GpuPageAtlas>(gl_, model.shared_pages(), form, budget_bytes,
                                                max_block_bytes_, 0);
    if (kept_atlas)
        *kept_atlas = pages_;
    memory_.index_bytes = table_bytes;
    memory_.interval_bytes = pages_->atlas_bytes() + pages_->column_bytes();
}

void GpuModel::upload_stacks(const sbrt::Model &model)
{
    if (layout_ == sbrt::GpuLayout::textures) {
        const sbrt::Frame &f = model.frame();
        index_texture_.emplace(gl_, f.cols, f.rows, sbrt::index_texels(model).data());
        interval_texture_.emplace(
            gl_, memory_.texture_cols, memory_.texture_rows,
            sbrt::interval_texels(model, memory_.texture_cols, memory_.texture_rows).data(),
            model.intervals().is_compact() ? 1 : 2);
        return;
    }
    // the model's own compact arrays go up as they are: counts and
    // intervals; only the group offsets narrow to 32 bits. The shader
    // reads their bytes as little-endian words.
    static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
                  "the GL path uploads the model's arrays as they lie in memory");
    group_offsets_.emplace(
        storage_buffer(gl_, sbrt::group_offset_words(model), max_block_bytes_, "stack offsets"));
    const sbrt::StackIndex &index = model.index();
    counts_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                    checked_bytes(index.count_data_bytes(), max_block_bytes_, "stack counts"),
                    index.count_data());
    const void *records = model.intervals().visit(
        [](const auto *first) { return static_cast<const void *>(first); });
    intervals_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                       checked_bytes(memory_.interval_bytes, max_block_bytes_, "intervals"),
                       records);
}

void GpuModel::bind() const
{
    if (pages_)
        pages_->bind();
    else if (layout_ == sbrt::GpuLayout::ssbo) {
        group_offsets_->bind(0);
        intervals_->bind(1);
        counts_->bind(6);
    }
    else {
        index_texture_->bind(0);
        interval_texture_->bind(1);
    }
    materials_.bind(3);
    pyramid_.bind(4);
}

void GpuModel::bind_pyramid(bool model_alone) const
{
    (model_alone && model_pyramid_ ? *model_pyramid_ : pyramid_).bind(4);
}

void GpuModel::bind_looks()
{
    if (!looks_) {
        const std::vector<sbrt::GpuLook> looks = sbrt::make_gpu_looks(tracer_);
        looks_.emplace(gl_, GL_SHADER_STORAGE_BUFFER, looks.size() * sizeof(sbrt::GpuLook),
                       looks.data());
    }
    looks_->bind(5);
}

void GpuModel::upload_overlays()
{
    const sbrt::GpuOverlays overlays = sbrt::make_gpu_overlays(tracer_);
    overlays_.emplace(storage_buffer(gl_, overlays.words, max_block_bytes_,
                                     "boreholes and fence panels"));
    logs_.emplace(storage_buffer(gl_, overlays.logs, max_block_bytes_, "borehole logs"));
    if (!overlays.cells.empty())
        cell_overlays_.emplace(
            storage_buffer(gl_, overlays.cells, max_block_bytes_, "cells' boreholes"));
    // with the model: the boxes of the boreholes' pass and its culling
    if (sbrt::gpu_overlay_mode(tracer_) == sbrt::GpuOverlayMode::with_model)
        boxes_.emplace(storage_buffer(gl_, sbrt::make_gpu_boxes(tracer_, tracer_.overlay_boxes()),
                                      max_block_bytes_, "boreholes' boxes"));
}

void GpuModel::bind_overlays()
{
    if (!overlays_)
        upload_overlays();
    overlays_->bind(9);
    logs_->bind(10);
    if (cell_overlays_)
        cell_overlays_->bind(11);
    if (boxes_)
        boxes_->bind(14);
}

} // namespace sbrt_gl
