/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The coarse first pass on the GPU (shaders/first_pass.comp):
 *            the tiles' first-hit bounds of a camera, computed once and
 *            read by every band's ray casting
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_tracer.hpp"

#include <cstring>

#include "gpu_internal.hpp"

namespace sbrt_gl {

std::vector<float> GpuTracer::tile_starts() const
{
    if (!tile_starts_)
        return {};
    const uint32_t side = uint32_t(sbrt::FIRST_PASS_TILE), tile_cols = first_pass_view_.counts[3];
    const uint32_t rows = first_pass_view_.grid[3];
    std::vector<float> starts(size_t(tile_cols) * ((rows + side - 1) / side));
    tile_starts_->download(starts.data(), starts.size() * sizeof(float));
    return starts;
}

sbrt::GpuView GpuTracer::traced_view(const sbrt::Camera &camera, uint32_t loop_budget)
{
    sbrt::GpuView view = sbrt::make_gpu_view(tracer_, camera, loop_budget);
    if (tracer_.pyramid().levels() == 0)
        return view; // no skipping, no first pass
    const uint32_t side = uint32_t(sbrt::FIRST_PASS_TILE);
    const uint32_t tile_cols = (uint32_t(camera.cols()) + side - 1) / side;
    const uint32_t tile_rows = (uint32_t(camera.rows()) + side - 1) / side;
    view.counts[2] = 1;
    view.counts[3] = tile_cols;
    // the bounds of this camera are there already: the same view but for
    // the band's rows
    sbrt::GpuView key = view;
    key.options[1] = key.options[2] = key.options[3] = 0;
    if (tile_starts_ && std::memcmp(&key, &first_pass_view_, sizeof key) == 0)
        return view;
    const auto start = Clock::now();
    first_pass_view_ = {}; // no bounds of any camera until these are done
    const size_t bytes = size_t(tile_cols) * tile_rows * sizeof(float);
    if (!tile_starts_ || tile_starts_->bytes() < bytes)
        tile_starts_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                             checked_bytes(bytes, max_block_bytes_, "first pass's tiles"));
    view_.upload(&view, sizeof view);
    view_.bind(0);
    model_.bind_pyramid();
    tile_starts_->bind(8);
    run_pass(Pass::first_pass, int(tile_cols), int(tile_rows));
    check_gl(gl_, "the first pass");
    first_pass_view_ = key;
    stats_.trace_ms += ms_since(start);
    return view;
}

} // namespace sbrt_gl
