/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The coarse first pass on the GPU: the tiles' first-hit bounds
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_first_pass.hpp"

#include <cstring>

#include "gpu_internal.hpp"
#include "tracing/cpu_tracing.hpp"

namespace sbrt_gl {

std::vector<float> GpuFirstPass::tile_starts() const
{
    if (!tile_starts_)
        return {};
    const uint32_t side = uint32_t(sbrt::FIRST_PASS_TILE), tile_cols = starts_view_.counts[3];
    const uint32_t rows = starts_view_.grid[3];
    std::vector<float> starts(size_t(tile_cols) * ((rows + side - 1) / side));
    tile_starts_->download(starts.data(), starts.size() * sizeof(float));
    return starts;
}

void GpuFirstPass::bind() const
{
    if (tile_starts_)
        tile_starts_->bind(8);
}

sbrt::GpuView GpuFirstPass::view(const sbrt::Camera &camera, uint32_t loop_budget)
{
    const sbrt::Tracer &tracer = passes_.tracer;
    sbrt::GpuView view = sbrt::make_gpu_view(tracer, camera, loop_budget);
    if (tracer.pyramid().levels() == 0)
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
    if (tile_starts_ && std::memcmp(&key, &starts_view_, sizeof key) == 0)
        return view;
    const auto start = Clock::now();
    starts_view_ = {}; // no bounds of any camera until these are done
    const size_t bytes = size_t(tile_cols) * tile_rows * sizeof(float);
    if (!tile_starts_ || tile_starts_->bytes() < bytes)
        tile_starts_.emplace(passes_.gl, GL_SHADER_STORAGE_BUFFER,
                             checked_bytes(bytes, passes_.max_block_bytes, "first pass's tiles"));
    passes_.view.upload(&view, sizeof view);
    passes_.view.bind(0);
    passes_.model.bind_pyramid();
    tile_starts_->bind(8);
    passes_.run_pass(Pass::first_pass, int(tile_cols), int(tile_rows));
    check_gl(passes_.gl, "the first pass");
    starts_view_ = key;
    passes_.stats.trace_ms += ms_since(start);
    return view;
}

} // namespace sbrt_gl
