/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The shading's inputs on the GPU
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_shading_inputs.hpp"

#include <vector>

#include "gpu_internal.hpp"
#include "gpu_stats.hpp"
#include "gpu/gpu_overlays.hpp"
#include "gpu/gpu_paint.hpp"

namespace sbrt_gl {

GpuShadingInputs::GpuShadingInputs(const GlApi &gl, const sbrt::Tracer &tracer, GpuModel &model,
                                   size_t max_block_bytes)
    : gl_(gl), tracer_(tracer), model_(model), max_block_bytes_(max_block_bytes)
{
}

void GpuShadingInputs::bind(const sbrt::GpuShade &shade, const sbrt::Shading &shading,
                            GpuStats &stats)
{
    if (!shade_)
        shade_.emplace(gl_, GL_UNIFORM_BUFFER, sizeof(sbrt::GpuShade));
    if (shading.drape && shading.drape != drape_on_gpu_) {
        // a GpuTracer meets one Drape (the module's, or the view server's
        // until it prepares the scene again: a new GpuTracer)
        const auto start = Clock::now();
        const std::vector<uint32_t> words = sbrt::make_gpu_drape(tracer_, *shading.drape);
        drape_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                       checked_bytes(words.size() * sizeof(uint32_t), max_block_bytes_,
                                     "drape (surface and texture)"),
                       words.data());
        drape_on_gpu_ = shading.drape;
        stats.upload_ms += ms_since(start);
    }
    if (shading.property || shading.fade) {
        // the words are made again only where what they show changed
        std::string key = sbrt::gpu_paint_key(shading);
        if (!paint_ || key != paint_key_) {
            const auto start = Clock::now();
            const std::vector<uint32_t> words = sbrt::make_gpu_paint(tracer_, shading);
            stats.paint_ms += ms_since(start);
            paint_.emplace(gl_, GL_SHADER_STORAGE_BUFFER,
                           checked_bytes(words.size() * sizeof(uint32_t), max_block_bytes_,
                                         "colours by voxel"),
                           words.data());
            paint_key_ = std::move(key);
            stats.upload_ms += ms_since(start);
        }
    }
    shade_->upload(&shade, sizeof shade);
    shade_->bind(1);
    model_.bind_looks();
    if (shading.drape)
        drape_->bind(7);
    if (shading.property || shading.fade)
        paint_->bind(7);
    if (sbrt::shaded_on_gpu(sbrt::gpu_overlay_mode(tracer_)))
        model_.bind_overlays();
}

void GpuShadingInputs::bind_double_rays(const sbrt::Camera &camera)
{
    const sbrt::GpuViewDouble exact = sbrt::make_gpu_view_double(tracer_, camera);
    if (!view_double_)
        view_double_.emplace(gl_, GL_UNIFORM_BUFFER, sizeof exact);
    view_double_->upload(&exact, sizeof exact);
    view_double_->bind(3);
}

} // namespace sbrt_gl
