/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GPU path's options and their automatic values
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_options.hpp"

#include <cstdlib>
#include <cstring>

#include "gl_context.hpp"

namespace sbrt_gl {

GpuOptions GpuOptions::from_environment(sbrt::GpuLayout layout)
{
    GpuOptions options;
    options.layout = layout;
    // a measurement's choice over the GPU's
    if (const char *bands = std::getenv("SBRT_GPU_BANDS")) {
        if (std::strcmp(bands, "staged") == 0)
            options.bands = BandStaging::staged;
        else if (std::strcmp(bands, "direct") == 0)
            options.bands = BandStaging::direct;
    }
    return options;
}

bool staged_bands(const GpuOptions &options, const std::string &renderer)
{
    // a GPU with memory of its own: the copy engine brings a band into
    // host memory; a software renderer's GPU memory is host memory
    if (options.bands == BandStaging::automatic)
        return !is_software_renderer(renderer);
    return options.bands == BandStaging::staged;
}

uint32_t loop_budget(const GpuOptions &options, const std::string &renderer)
{
    // llvmpipe ends an invocation after 65,535 loop iterations; a GPU does
    // not: its rays run to the end
    if (options.loop_budget)
        return *options.loop_budget;
    return is_software_renderer(renderer) ? sbrt::GPU_LOOP_BUDGET : UNBOUNDED_LOOP_BUDGET;
}

} // namespace sbrt_gl
