/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What the GPU tracer's passes share: dispatches, programs and
 *            the paging of a paged model
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_pass_context.hpp"

#include <algorithm>

#include "gpu_internal.hpp"
#include "util/error.hpp"

namespace sbrt_gl {

void PassContext::upload_view(sbrt::GpuView &block, int first, int count) const
{
    block.options[2] = uint32_t(first);
    block.options[3] = uint32_t(count);
    view.upload(&block, sizeof block); // stays bound to index 0
}

void PassContext::dispatch(Pass pass, int width, int height) const
{
    timer.time(int(pass), [&] {
        gl.DispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    });
}

void PassContext::run_pass(Pass pass, int width, int height) const
{
    programs.get(pass).use();
    dispatch(pass, width, height);
    gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

GlComputeProgram &PassContext::shading_program(const sbrt::Shading &shading, Pass pass) const
{
    const bool draped = shading.drape != nullptr;
    // colours by voxel: only the model pass of face normals (gpu_paints)
    const bool painted = shading.property || shading.fade;
    if (painted && pass != Pass::shade)
        sbrt::fail("colours by voxel are not made in this GPU pass");
    return programs.get(pass, {draped, painted});
}

bool PassContext::brought_wanted_blocks() const
{
    GpuPageAtlas *pages = model.pages();
    if (!pages)
        return false;
    const auto start = Clock::now();
    const bool brought = pages->bring_wanted() > 0;
    stats.page_ms += ms_since(start);
    stats.page_passes += brought ? 1 : 0;
    return brought;
}

PassContext::BandPaging PassContext::begin_band() const
{
    const GpuPageAtlas *pages = model.pages();
    return {pages ? pages->figures().not_placed : 0, false};
}

bool PassContext::band_again(BandPaging &band) const
{
    if (brought_wanted_blocks())
        return true;
    GpuPageAtlas *pages = model.pages();
    if (band.restarted || !pages || pages->figures().not_placed == band.no_room_before)
        return false;
    pages->begin_band_again();
    band.restarted = true;
    return true;
}

int PassContext::crowded_band_rows(int cols) const
{
    const GpuPageAtlas *pages = model.pages();
    if (!pages || !pages->crowded())
        return 0;
    return std::max(1, crowded_band_pixels / std::max(cols, 1));
}

} // namespace sbrt_gl
