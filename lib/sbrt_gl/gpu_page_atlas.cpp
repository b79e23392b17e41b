/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   A paged model's blocks brought up to the GPU as rays want them
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_page_atlas.hpp"

#include <algorithm>
#include <memory>

#include "gpu_internal.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace sbrt_gl {

namespace {

/// Blocks decoded at once before they go up: bounds the host's copies.
constexpr size_t UPLOAD_CHUNK = 64;

/// The page table: its head, then every page missing.
std::vector<uint32_t> empty_table(const sbrt::StackPages &pages, bool column_pages)
{
    std::vector<uint32_t> words = sbrt::gpu_page_table_head(pages, column_pages);
    words.resize(words.size() + size_t(sbrt::gpu_page_count(pages, column_pages)),
                 sbrt::GPU_PAGE_MISSING);
    return words;
}

/// A storage buffer of the model's column records `records` (a range or a
/// top interval a column), as they lie in memory.
GlBuffer column_buffer(const GlApi &gl, const void *records, uint64_t bytes, size_t limit,
                       const char *what)
{
    return GlBuffer(gl, GL_SHADER_STORAGE_BUFFER, checked_bytes(size_t(bytes), limit, what),
                    records);
}

/// The columns' ranges as the shaders read them (two floats a column),
/// widened a slice at a time where held compact.
GlBuffer ranges_buffer(const GlApi &gl, const sbrt::ColumnRangeArray &ranges, size_t limit)
{
    const uint64_t bytes = uint64_t(ranges.size()) * sizeof(sbrt::ZRange);
    if (!ranges.is_compact())
        return column_buffer(gl, ranges.wide_data(), bytes, limit, "columns' ranges");
    GlBuffer buffer = column_buffer(gl, nullptr, bytes, limit, "columns' ranges");
    constexpr size_t SLICE = size_t(1) << 20;
    std::vector<sbrt::ZRange> wide;
    for (size_t at = 0; at < ranges.size(); at += SLICE) {
        wide.resize(std::min(SLICE, ranges.size() - at));
        for (size_t i = 0; i < wide.size(); ++i)
            wide[i] = ranges[at + i];
        buffer.write(at * sizeof(sbrt::ZRange), wide.data(), wide.size() * sizeof(sbrt::ZRange));
    }
    return buffer;
}

} // namespace

uint64_t atlas_words(uint64_t budget_bytes, size_t max_block_bytes)
{
    return std::min<uint64_t>(budget_bytes, max_block_bytes) / 4;
}

GpuPageAtlas::GpuPageAtlas(const GlApi &gl,
                           const std::shared_ptr<const sbrt::StackPages> &shared_pages,
                           const PagedForm &form, uint64_t budget_bytes, size_t max_block_bytes,
                           unsigned threads)
    : gl_(gl), pages_(*shared_pages), owner_(shared_pages), form_(form),
      page_count_(sbrt::gpu_page_count(*shared_pages, form.column_pages)), threads_(threads),
      asked_words_(atlas_words(budget_bytes, max_block_bytes)),
      residency_(page_count_, asked_words_), mark_words_(sbrt::gpu_mark_words(page_count_)),
      table_(gl_, GL_SHADER_STORAGE_BUFFER,
             checked_bytes((size_t(sbrt::GPU_PAGE_TABLE_HEAD) + size_t(page_count_)) * 4,
                           max_block_bytes, "page table"),
             empty_table(pages_, form.column_pages).data()),
      atlas_(gl_, GL_SHADER_STORAGE_BUFFER, size_t(residency_.atlas_words()) * 4),
      marks_(gl_, GL_SHADER_STORAGE_BUFFER, size_t(mark_words_) * 2 * 4)
{
    if (form.ranges_whole)
        ranges_.emplace(ranges_buffer(gl_, pages_.column_ranges(), max_block_bytes));
    if (form.tops_whole) {
        const sbrt::IntervalArray &tops = pages_.column_tops();
        tops_.emplace(column_buffer(
            gl_, tops.visit([](const auto *first) { return static_cast<const void *>(first); }),
            uint64_t(tops.size()) * tops.record_bytes(), max_block_bytes, "columns' tops"));
    }
    begin_frame();
}

bool GpuPageAtlas::serves(const sbrt::StackPages &pages, const PagedForm &form,
                          uint64_t budget_bytes, size_t max_block_bytes) const
{
    return owner_.lock().get() == &pages && form == form_ &&
           atlas_words(budget_bytes, max_block_bytes) == asked_words_;
}

uint64_t GpuPageAtlas::column_bytes() const
{
    return (ranges_ ? ranges_->bytes() : 0) + (tops_ ? tops_->bytes() : 0);
}

void GpuPageAtlas::bind() const
{
    table_.bind(0);
    atlas_.bind(1);
    marks_.bind(6);
    if (tops_)
        tops_->bind(15);
    if (ranges_)
        ranges_->bind(16);
}

void GpuPageAtlas::begin_frame()
{
    residency_.begin_frame();
    // after the last frame's marks were set
    gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const GLuint zero = 0;
    gl_.BindBuffer(GL_SHADER_STORAGE_BUFFER, marks_.name());
    gl_.ClearBufferSubData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, 0, GLsizeiptr(marks_.bytes()),
                           GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void GpuPageAtlas::begin_band_again()
{
    begin_frame();
    ++figures_.band_restarts;
}

std::vector<int> GpuPageAtlas::marked(const std::vector<uint32_t> &marks, int part) const
{
    std::vector<int> blocks;
    for (uint32_t w = 0; w < mark_words_; ++w)
        for (uint32_t bits = marks[size_t(part) * mark_words_ + w]; bits != 0; bits &= bits - 1)
            blocks.push_back(int(w * 32 + uint32_t(__builtin_ctz(bits))));
    return blocks;
}

int GpuPageAtlas::bring_wanted()
{
    // the shaders' marks, once the dispatches that set them are done
    gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> marks(size_t(mark_words_) * 2);
    marks_.download(marks.data(), marks.size() * 4);
    // the blocks this frame read stay
    for (int b : marked(marks, 1))
        if (b < page_count_)
            residency_.mark_read(b);
    std::vector<int> wanted;
    // (a page that found no room in this frame is not decoded again)
    for (int b : marked(marks, 0))
        if (b < page_count_ && !residency_.holds(b) && !residency_.found_no_room(b))
            wanted.push_back(b);
    // columns' pages first: a ray reads its cell's before any block
    std::stable_partition(wanted.begin(), wanted.end(),
                          [&](int p) { return p >= pages_.block_count(); });
    return wanted.empty() ? 0 : upload(wanted);
}

void GpuPageAtlas::set_entry(int b, uint32_t base)
{
    table_.write((size_t(sbrt::GPU_PAGE_TABLE_HEAD) + size_t(b)) * 4, &base, 4);
}

std::vector<uint32_t> GpuPageAtlas::page_words(int p) const
{
    const int blocks = pages_.block_count();
    if (p >= blocks)
        return sbrt::gpu_column_page_words(pages_, p - blocks, form_.compact);
    return sbrt::gpu_block_words(*pages_.block(p), form_.compact);
}

int GpuPageAtlas::upload(const std::vector<int> &wanted)
{
    const auto start = Clock::now();
    int placed = 0;
    bool full = false; // a block found no room: the later chunks are not decoded
    for (size_t first = 0; first < wanted.size() && !full; first += UPLOAD_CHUNK) {
        const size_t count = std::min(UPLOAD_CHUNK, wanted.size() - first);
        std::vector<std::vector<uint32_t>> words(count);
        sbrt::for_each_row(0, int(count), threads_,
                           [&](int k) { words[size_t(k)] = page_words(wanted[first + size_t(k)]); });
        for (size_t k = 0; k < count; ++k) {
            const int b = wanted[first + k];
            std::vector<int> dropped;
            const std::optional<uint32_t> base = residency_.place(b, words[k].size(), dropped);
            for (int old : dropped)
                set_entry(old, sbrt::GPU_PAGE_MISSING);
            figures_.dropped += dropped.size();
            if (!base) {
                ++figures_.not_placed;
                full = true; // the rest wait for another band's call
                continue;
            }
            atlas_.write(size_t(*base) * 4, words[k].data(), words[k].size() * 4);
            set_entry(b, *base);
            ++placed;
            ++figures_.uploads;
            figures_.upload_bytes += words[k].size() * 4;
        }
    }
    check_gl(gl_, "bringing the model's blocks up to the GPU");
    figures_.upload_ms += ms_since(start);
    return placed;
}

} // namespace sbrt_gl
