/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   A paged model on the GPU within a budget (issue 49): its
 *            blocks that rays reach in one atlas, found through a page
 *            table; the blocks a dispatch found missing, marked by the GPU,
 *            decoded and brought up for the dispatch again
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_GPU_PAGE_ATLAS_HPP
#define SBRT_GL_GPU_PAGE_ATLAS_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "gl_api.hpp"
#include "gl_objects.hpp"
#include "gpu/gpu_pages.hpp"

namespace sbrt_gl {

/// What a page atlas did since it was made.
struct PageFigures {
    uint64_t uploads = 0;       ///< blocks brought up (again after dropped too)
    uint64_t upload_bytes = 0;  ///< their words
    uint64_t dropped = 0;       ///< blocks dropped for others' room
    uint64_t not_placed = 0;    ///< wanted blocks the frame's own left no room for
    uint64_t band_restarts = 0; ///< bands that let earlier bands' blocks go (begin_band_again)
    double upload_ms = 0;       ///< decoding and uploading them
};

/// What a paged model holds on the GPU beside its blocks (GpuPageAtlas).
struct PagedForm {
    bool compact = false;      ///< intervals a word each (every block's are exact so)
    /// its columns' top intervals and ranges in pages of their own
    /// (sbrt::gpu_column_page_words), numbered after the blocks'
    bool column_pages = false;
    bool ranges_whole = false; ///< each column's range (the pyramid's level 0), binding 16
    bool tops_whole = false;   ///< each column's top interval, binding 15
    bool operator==(const PagedForm &o) const
    {
        return compact == o.compact && column_pages == o.column_pages &&
               ranges_whole == o.ranges_whole && tops_whole == o.tops_whole;
    }
};

/// \brief The GPU's part of a paged model (`pages`): the page table
/// (binding 0), the atlas of at most `budget_bytes` (binding 1) and the
/// marks the shaders set (binding 6: the blocks wanted and those read,
/// shaders/common/layout.glsl). No block is up at first: a dispatch marks
/// the blocks its rays find missing and sends those rays back;
/// bring_wanted() then brings the blocks up (the frame's blocks stay, the
/// least recently used others go), and the dispatch runs again. The
/// context must be current.
class GpuPageAtlas {
public:
    /// `form`: the blocks' words, the columns' pages, and the columns
    /// held whole (uploaded here: they are the model's, whatever the
    /// scene); `max_block_bytes`: the GPU's largest storage buffer, which
    /// bounds the atlas too; `threads` decode blocks (0: all cores).
    GpuPageAtlas(const GlApi &gl, const std::shared_ptr<const sbrt::StackPages> &pages,
                 const PagedForm &form, uint64_t budget_bytes, size_t max_block_bytes,
                 unsigned threads);

    /// Whether this atlas holds the pages of `pages` (still alive) in the
    /// form and size asked for: a tracer of another scene of the same model
    /// may take it over, with its pages and columns already up.
    bool serves(const sbrt::StackPages &pages, const PagedForm &form, uint64_t budget_bytes,
                size_t max_block_bytes) const;

    /// The page table, the atlas, the marks and the columns held whole.
    void bind() const;
    /// A new frame: no block marked (a GL command: after the last
    /// frame's dispatches); blocks the last frame used may go.
    void begin_frame();
    /// Once the dispatches so far are done: the blocks they marked wanted
    /// and that are not up, decoded and brought up where room is made;
    /// how many. 0: a dispatch again would find the same blocks missing.
    int bring_wanted();
    /// The frame begun again (no page marked; those the earlier bands used
    /// may go), where a band's pages found no room: the band, dispatched
    /// again, brings up its own pages in their room. A frame whose pages
    /// exceed the atlas then runs on the GPU band by band where each
    /// band's pages fit.
    void begin_band_again();
    /// Whether a frame's blocks ever found no room, or the columns are
    /// paged (a model too large for its pyramid): frames then go in bands
    /// small enough for each band's pages to fit.
    bool crowded() const { return figures_.not_placed > 0 || column_pages(); }
    const PagedForm &form() const { return form_; }
    bool column_pages() const { return form_.column_pages; }
    /// Bytes of the columns held whole (ranges, tops).
    uint64_t column_bytes() const;
    uint64_t atlas_bytes() const { return residency_.atlas_words() * 4; }
    uint64_t held_bytes() const { return residency_.held_words() * 4; }
    int held_blocks() const { return residency_.held_blocks(); }
    const PageFigures &figures() const { return figures_; }

private:
    /// Marks of half `part` (0 wanted, 1 read) as page numbers.
    std::vector<int> marked(const std::vector<uint32_t> &marks, int part) const;
    /// Page p's words: block p's, or the columns' of block p - block_count.
    std::vector<uint32_t> page_words(int p) const;
    /// Pages `wanted` decoded (in parallel) and put into the atlas.
    int upload(const std::vector<int> &wanted);
    void set_entry(int b, uint32_t base);

    /// a copy: the atlas may outlive the tracer that made it (kept_atlas)
    const GlApi gl_;
    const sbrt::StackPages &pages_;
    std::weak_ptr<const sbrt::StackPages> owner_; ///< serves(): the same model
    PagedForm form_;
    int page_count_; ///< the blocks', then where asked their columns'
    unsigned threads_;
    uint64_t asked_words_; ///< atlas_words of the budget given (serves())
    sbrt::PageResidency residency_;
    uint32_t mark_words_;
    GlBuffer table_, atlas_, marks_;
    std::optional<GlBuffer> ranges_, tops_; ///< the columns held whole
    PageFigures figures_;
};

/// The atlas words of a budget of `budget_bytes` on a GPU whose largest
/// storage buffer is `max_block_bytes`.
uint64_t atlas_words(uint64_t budget_bytes, size_t max_block_bytes);

} // namespace sbrt_gl

#endif
