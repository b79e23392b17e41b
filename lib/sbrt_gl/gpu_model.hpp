/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What stays on the GPU for a prepared scene: the model's
 *            stacks in their layout, the materials, the empty-space
 *            pyramids, how the materials look, the boreholes and curtains
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_MODEL_HPP
#define SBRT_GL_GPU_MODEL_HPP

#include <cstddef>
#include <optional>

#include "gl_api.hpp"
#include "gl_objects.hpp"
#include "gpu_options.hpp"
#include "gpu_page_atlas.hpp"
#include "gpu/gpu_memory_layout.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

/// How the model is held on the GPU, as its programs read it (GpuModel).
struct ModelForm {
    sbrt::GpuLayout layout = sbrt::GpuLayout::ssbo;
    bool paged = false;       ///< its blocks in a page atlas (SBRT_PAGED)
    bool column_tops = false; ///< with each column's top interval (SBRT_COLUMN_TOPS)
    /// each column's range (the pyramid's level 0) beside the pyramid's
    /// levels above (SBRT_COLUMN_RANGES)
    bool column_ranges = false;
    /// both in pages of the blocks' columns (SBRT_COLUMN_PAGES)
    bool column_pages = false;
};

/// How a paged model goes to the GPU within its budget (GpuModel): the
/// scene's pyramid from `first_level` on, and what the atlas holds beside
/// the blocks (its columns' ranges and top intervals whole, or in pages).
struct PagedPlan {
    int first_level = 0;
    PagedForm form;
};

/// \brief The resident part of a GPU tracer: the model of `tracer` uploaded
/// once, at construction, in `layout` (the stack index and the intervals
/// as two storage buffers or two textures), its materials and pyramids;
/// how the materials look and the scene's boreholes and curtains go up
/// when first bound. Each is owned by its GL object (gl_objects.hpp) and
/// released with the GpuModel; the context must be current. Binds them at
/// the bindings the shaders declare (shaders/common/layout.glsl).
/// A paged model (Model::is_paged) goes up as its blocks are wanted, into
/// an atlas (GpuPageAtlas; layout ssbo, no boreholes or curtains) within
/// `page_budget_bytes`. Beside it, held by the atlas (and so kept with it
/// from one scene to the next): each column's range, the pyramid's level 0,
/// with the scene's levels above (together at most half the budget), and
/// each column's top interval where the model holds them
/// (StackPages::column_tops) and they take at most half of what is left:
/// a ray that meets only a column's top interval needs no block. Where
/// they do not fit so (a model many times national), the columns' top
/// intervals and ranges go up in pages of their own as rays want them, and
/// the pyramid from the first level that takes at most a quarter of the
/// budget (an error where none does, or where the model holds no tops).
class GpuModel {
public:
    /// `max_block_bytes`: the GPU's largest storage buffer binding (an
    /// error names what exceeds it); of `options`, the layout, the page
    /// budget, the kept atlas and column_pages_from_level.
    GpuModel(const GlApi &gl, const sbrt::Tracer &tracer, const GpuOptions &options,
             size_t max_block_bytes);
    GpuModel(const GpuModel &) = delete;
    GpuModel &operator=(const GpuModel &) = delete;

    /// The stack index and intervals (bindings 0, 1 and in the ssbo layout
    /// 6), the materials (3) and the pyramid (4).
    void bind() const;
    /// At binding 4: the pyramid of the model alone where boreholes drawn
    /// with it (`model_alone`) have one of their own, else the scene's.
    void bind_pyramid(bool model_alone = false) const;
    /// How each material looks (binding 5).
    void bind_looks();
    /// The boreholes and curtains the shading program draws (bindings 9,
    /// 10, where cells list theirs 11, with the model their boxes 14).
    void bind_overlays();

    sbrt::GpuLayout layout() const { return layout_; }
    /// How its programs read it.
    ModelForm form() const
    {
        const PagedForm &p = plan_.form;
        return {layout_, pages_ != nullptr, p.tops_whole || p.column_pages, p.ranges_whole,
                p.column_pages};
    }
    /// How a paged model went up within its budget.
    const PagedPlan &plan() const { return plan_; }
    /// A paged model's atlas; null where the model is up whole.
    GpuPageAtlas *pages() { return pages_.get(); }
    const GpuPageAtlas *pages() const { return pages_.get(); }
    /// What the model takes on the GPU in its layout.
    const sbrt::GpuMemory &memory() const { return memory_; }
    /// Bytes of the empty-space pyramid.
    size_t pyramid_bytes() const { return pyramid_.bytes(); }

private:
    void upload_stacks(const sbrt::Model &model);
    /// The atlas of a paged model, refused where it cannot be paged.
    void open_pages(const sbrt::Model &model, uint64_t budget_bytes,
                    std::shared_ptr<GpuPageAtlas> *kept_atlas);
    void upload_overlays();

    const GlApi &gl_;
    const sbrt::Tracer &tracer_;
    size_t max_block_bytes_;
    sbrt::GpuLayout layout_;
    PagedPlan plan_; ///< a paged model's
    sbrt::GpuMemory memory_;
    std::shared_ptr<GpuPageAtlas> pages_; ///< a paged model's blocks and columns
    /// the stacks: group offsets, stack counts, intervals (ssbo), or the
    /// index and the intervals as textures
    std::optional<GlBuffer> group_offsets_, counts_, intervals_;
    std::optional<GlUintTexture> index_texture_, interval_texture_;
    GlBuffer materials_;
    GlBuffer pyramid_; ///< empty-space skipping (levels() 0: off)
    /// the model's alone, where boreholes drawn with it fill theirs
    std::optional<GlBuffer> model_pyramid_;
    std::optional<GlBuffer> looks_;
    /// boreholes and curtains, their logs, each cell's boreholes, and with
    /// the model the boxes of the boreholes' pass and its culling
    std::optional<GlBuffer> overlays_, logs_, cell_overlays_, boxes_;
};

} // namespace sbrt_gl

#endif
