/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The mapped, fenced band buffers of the GPU's frames
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "mapped_bands.hpp"

#include <algorithm>
#include <cstring>

#include "gpu_internal.hpp"
#include "util/error.hpp"

namespace sbrt_gl {

MappedBands::MappedBands(const GlApi &gl, size_t max_bytes, bool staged)
    : gl_(gl), max_bytes_(max_bytes), staged_(staged)
{
}

void MappedBands::begin_frame()
{
    drop_queued();
    layout_.reset();
}

void MappedBands::drop_queued()
{
    // their slots come next again: skipping one would hand the GPU the
    // slot of a band the sink may still read; and not before the GPU is
    // done with them (the host writes a slot's count before a dispatch)
    if (!queued_.empty())
        next_slot_ = queued_.front().slot;
    for (const Queued &band : queued_)
        band.fence.wait();
    queued_.clear();
}

void MappedBands::set_scratch(size_t bytes, GLuint binding)
{
    scratch_binding_ = binding;
    if (bytes == 0) {
        scratch_.clear();
        return;
    }
    if (!scratch_.empty() && scratch_.front().bytes() >= bytes)
        return;
    drop_queued(); // their dispatches use the buffers replaced here
    scratch_.clear();
    for (int k = 0; k < SLOTS; ++k)
        scratch_.emplace_back(gl_, GL_SHADER_STORAGE_BUFFER, bytes);
}

std::optional<sbrt::GpuBandLayout> MappedBands::layout(int rows, int cols,
                                                       const sbrt::Outputs &outputs)
{
    if (layout_) {
        // the frame's while it holds the band: as wide, the same outputs
        if (layout_->rows >= rows && layout_->cols == cols &&
            (layout_->material_at != 0) == outputs.material &&
            (layout_->elevation_at != 0) == outputs.elevation &&
            (layout_->depth_at != 0) == outputs.depth)
            return layout_;
        drop_queued(); // another layout after all
    }
    const sbrt::GpuBandLayout wanted = sbrt::gpu_band_layout(rows, cols, outputs);
    if (wanted.bytes() > max_bytes_)
        return std::nullopt;
    if (slots_.empty() || slots_.front().bytes() < wanted.bytes()) {
        drop_queued();
        slots_.clear();
        device_slots_.clear();
        for (int k = 0; k < SLOTS; ++k) {
            slots_.emplace_back(gl_, wanted.bytes());
            if (staged_)
                device_slots_.emplace_back(gl_, GL_SHADER_STORAGE_BUFFER, wanted.bytes());
        }
    }
    layout_ = wanted;
    return layout_;
}

void MappedBands::queue(int first, int count, const std::function<void(int, int, int)> &dispatch,
                        int slot)
{
    if (slot < 0) {
        slot = next_slot_;
        next_slot_ = (next_slot_ + 1) % SLOTS;
    }
    const MappedBuffer &buffer = slots_[size_t(slot)];
    // no ray over the budget yet: the host writes the count, which the
    // GPU sees in the commands queued after (a coherent mapping)
    const uint32_t zero = 0;
    const size_t count_at = layout_->over_budget_at * 4;
    if (!scratch_.empty())
        scratch_[size_t(slot)].bind(scratch_binding_);
    if (staged_) {
        GlBuffer &device = device_slots_[size_t(slot)];
        device.write(count_at, &zero, 4);
        device.bind(2);
        dispatch(first, count, slot);
        // the outputs and the count into the mapped buffer, on the GPU
        gl_.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        gl_.BindBuffer(GL_COPY_READ_BUFFER, device.name());
        gl_.BindBuffer(GL_COPY_WRITE_BUFFER, buffer.name());
        const size_t copied = std::min(layout_->bytes(), count_at + 4 + 4 * STAGED_SENT_BACK);
        gl_.CopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0,
                              GLsizeiptr(copied));
    }
    else {
        std::memcpy(buffer.host() + count_at, &zero, 4);
        buffer.bind(2);
        dispatch(first, count, slot);
    }
    gl_.MemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    check_gl(gl_, "the shading dispatch");
    queued_.push_back({first, count, slot, GlFence(gl_)});
}

uint8_t *MappedBands::band(int first, int count, int image_rows,
                           const std::function<void(int, int, int)> &dispatch)
{
    if (!layout_ || count > layout_->rows)
        sbrt::fail("MappedBands::band: ", count, " rows without a layout that holds them");
    const auto start = Clock::now();
    if (queued_.empty() || queued_.front().first != first || queued_.front().count != count) {
        drop_queued(); // not the band that was dispatched ahead
        queue(first, count, dispatch);
    }
    const int next = first + count;
    if (next < image_rows && queued_.size() == 1)
        queue(next, std::min(count, image_rows - next), dispatch);
    uint8_t *host = take_front();
    gpu_ms_ += ms_since(start);
    return host;
}

uint8_t *MappedBands::redo(const std::function<void(int, int, int)> &dispatch)
{
    const auto start = Clock::now();
    // the band dispatched ahead is dropped (its slot comes next again), and
    // this one goes into its own: no slot the sink may hold is written
    drop_queued();
    queue(last_first_, last_count_, dispatch, last_slot_);
    uint8_t *host = take_front();
    gpu_ms_ += ms_since(start);
    return host;
}

uint8_t *MappedBands::take_front()
{
    const Queued &band = queued_.front();
    band.fence.wait();
    last_done_ = Clock::now();
    last_slot_ = band.slot;
    last_first_ = band.first;
    last_count_ = band.count;
    uint8_t *host = slots_[size_t(band.slot)].host();
    if (staged_) {
        // the pixels sent back beyond those the copy brought: read back
        uint32_t over = 0;
        std::memcpy(&over, host + layout_->over_budget_at * 4, 4);
        if (over > STAGED_SENT_BACK) {
            const size_t at = (layout_->over_budget_at + 1 + STAGED_SENT_BACK) * 4;
            device_slots_[size_t(band.slot)].download(at, host + at,
                                                     size_t(over - STAGED_SENT_BACK) * 4);
        }
    }
    queued_.pop_front();
    return host;
}

void PassTimer::time(int pass, const std::function<void()> &commands)
{
    if (!on_) {
        commands();
        return;
    }
    if (passes_.size() == pool_.size())
        pool_.emplace_back(gl_);
    const GlTimeQuery &query = pool_[passes_.size()];
    query.begin();
    commands();
    query.end();
    passes_.push_back(pass);
}

std::vector<double> PassTimer::take_ms(int passes)
{
    std::vector<double> ms(size_t(passes), 0.0);
    for (size_t k = 0; k < passes_.size(); ++k)
        if (passes_[k] >= 0 && passes_[k] < passes)
            ms[size_t(passes_[k])] += pool_[k].ms();
    passes_.clear();
    return ms;
}

} // namespace sbrt_gl
