/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Where a frame's shaded bands land: buffers mapped into host
 *            memory, written by the shading pass in the bytes the caller
 *            asked for, fenced, each band dispatched while the host still
 *            hands on the one before; the sink reads the mapped memory
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_MAPPED_BANDS_HPP
#define SBRT_GL_MAPPED_BANDS_HPP

#include <chrono>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

#include "gl_objects.hpp"
#include "gpu/gpu_layout.hpp"
#include "tracing/cpu_tracing.hpp"

namespace sbrt_gl {

/// \brief The shaded bands of one frame at a time. On a GPU with memory of
/// its own (`staged`) the shading pass writes a band there and the GPU's
/// copy engine brings it into the mapped buffer before its fence (sooner
/// than the shader writing across PCIe: docs/performance.md); on a
/// software renderer, whose GPU memory is host
/// memory, the shading pass writes the mapped buffer itself.
/// The GPU tracer's options choose (GpuOptions::bands). Band k of a
/// frame lies in the next slot: the renderer has at most
/// sbrt::RowTracer::SINK_BANDS bands out, the one being filled among them,
/// so while band k is handed over the sink holds at most band k - 1, and
/// band k + 1, dispatched ahead, goes to the slot of band k - 2: no slot is
/// written while the host reads it. Nothing is copied or converted on the
/// host.
class MappedBands {
public:
    static constexpr int SLOTS = 3;
    /// Staged bands: the first this many pixels the GPU sends back to the
    /// host (over its loop budget, or colours by voxel it cannot decide)
    /// come into the mapped buffer with the outputs, by the GPU's copy: a
    /// read of GPU memory by the host waits for all the GL queued (longer
    /// than the frame itself). More are read back after the fence.
    static constexpr size_t STAGED_SENT_BACK = 4096;
    static_assert(SLOTS >= int(sbrt::RowTracer::SINK_BANDS) + 1,
                  "a slot for each band out and one dispatched ahead");

    /// `max_bytes`: the GPU's largest storage buffer binding.
    MappedBands(const GlApi &gl, size_t max_bytes, bool staged);
    bool staged() const { return staged_; }

    /// A new frame: what was dispatched ahead for the last one is dropped
    /// (its slot is written again only by commands queued after it).
    void begin_frame();
    /// The layout of a band of up to `rows` x `cols` of `outputs`: the
    /// frame's (its first band's rows) while that holds it; nullopt where
    /// it would not fit a storage buffer.
    std::optional<sbrt::GpuBandLayout> layout(int rows, int cols, const sbrt::Outputs &outputs);
    /// Rows [first, first + count) of an image of `image_rows`, laid out as
    /// the frame's layout: dispatched by `dispatch(first, count, slot)` with
    /// the slot bound to storage binding 2 (unless the last call dispatched it
    /// ahead); then the next band (as many rows) dispatched ahead; returns
    /// the band's memory once the GPU is done with it.
    uint8_t *band(int first, int count, int image_rows,
                  const std::function<void(int, int, int)> &dispatch);
    /// The band band() returned last, dispatched again into its own slot
    /// (what the host read of it is overwritten; the band dispatched
    /// ahead is dropped), once the GPU is done with it.
    uint8_t *redo(const std::function<void(int, int, int)> &dispatch);

    /// A GPU buffer of `bytes` for each slot (none: 0), bound to storage
    /// binding `binding` with its slot for each dispatch: what a band's
    /// passes keep between them while the next band is dispatched.
    void set_scratch(size_t bytes, GLuint binding);
    /// When the GPU was last found done with a band (the host's time from
    /// there on is what follows the last dispatch).
    std::chrono::steady_clock::time_point last_done() const { return last_done_; }
    /// The slot of the band band() returned last (the `slot` its dispatch
    /// was given).
    int last_slot() const { return last_slot_; }
    /// Milliseconds spent queueing dispatches and waiting for their fences.
    double gpu_ms() const { return gpu_ms_; }
    void reset_gpu_ms() { gpu_ms_ = 0; }

private:
    struct Queued {
        int first, count, slot;
        GlFence fence;
    };
    /// Forgets the bands dispatched and not handed out.
    void drop_queued();
    /// Dispatches rows [first, first + count) into the next slot (or into
    /// `slot` where given).
    void queue(int first, int count, const std::function<void(int, int, int)> &dispatch,
               int slot = -1);
    /// The front band's memory once the GPU is done with it (unqueued).
    uint8_t *take_front();

    const GlApi &gl_;
    size_t max_bytes_;
    std::optional<sbrt::GpuBandLayout> layout_; ///< the frame's
    bool staged_;
    std::vector<MappedBuffer> slots_;
    std::vector<GlBuffer> device_slots_; ///< staged: where the GPU writes
    std::vector<GlBuffer> scratch_;      ///< set_scratch's, a slot each
    GLuint scratch_binding_ = 0;
    std::deque<Queued> queued_;
    int next_slot_ = 0, last_slot_ = 0;
    int last_first_ = 0, last_count_ = 0; ///< the rows of the band last returned
    std::chrono::steady_clock::time_point last_done_{};
    double gpu_ms_ = 0;
};

/// \brief GL_TIME_ELAPSED of each pass of a frame, where asked for
/// (trace_bench): queries come from a pool, their results are read once the
/// frame is done.
class PassTimer {
public:
    explicit PassTimer(const GlApi &gl) : gl_(gl) {}
    void enable(bool on) { on_ = on; }
    bool enabled() const { return on_; }
    /// Runs `commands` (GL calls) inside a query of `pass` when enabled.
    void time(int pass, const std::function<void()> &commands);
    /// Milliseconds per pass of the queries since the last call (waits for
    /// their results); pass numbers index the vector.
    std::vector<double> take_ms(int passes);

private:
    const GlApi &gl_;
    bool on_ = false;
    std::vector<GlTimeQuery> pool_;
    std::vector<int> passes_; ///< the pass of each query in use, in order
};

} // namespace sbrt_gl

#endif
