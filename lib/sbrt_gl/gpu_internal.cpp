/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   What the GPU tracer's files share: the programs' sources,
 *            timing, buffer sizes
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gpu_internal.hpp"

#include <algorithm>
#include <limits>

#include "shader_sources.hpp"
#include "tracing/cpu_tracing.hpp"
#include "gpu/gpu_overlays.hpp"
#include "util/error.hpp"

#define SBRT_STRINGIFY(x) #x

namespace sbrt_gl {

double ms_since(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

size_t checked_bytes(size_t bytes, size_t limit, const char *what)
{
    if (bytes > limit)
        sbrt::fail("the model's ", what, " take ", bytes,
                   " bytes, more than this GPU's largest storage buffer (",
                   limit, " bytes): render with backend=cpu");
    return bytes;
}

/// A storage buffer for up to `rows` rows of `row_bytes`, within the GPU's
/// largest binding: the one in `buffer` where it is large enough.
void ensure_band_buffer(const GlApi &gl, std::optional<GlBuffer> &buffer, int rows,
                        size_t row_bytes, size_t max_block_bytes)
{
    if (row_bytes > max_block_bytes)
        sbrt::fail("an image row of ", row_bytes, " bytes does not fit a storage buffer");
    const size_t bytes = std::min(size_t(rows), max_block_bytes / row_bytes) * row_bytes;
    if (!buffer || buffer->bytes() < bytes)
        buffer.emplace(gl, GL_SHADER_STORAGE_BUFFER, bytes);
}


bool compact_on_gpu(const sbrt::Model &model)
{
    if (!model.is_paged())
        return model.intervals().is_compact();
    const sbrt::Stats stats = model.stats();
    return stats.interval_bytes <= stats.intervals * 4;
}

/// The first pass's tile and budget, as the CPU's (cpu_tracing.hpp).
namespace {

const char *const FIRST_PASS_DEFINES =
    "#define SBRT_FIRST_PASS_TILE " SBRT_STRINGIFY(8) "\n"
    "#define SBRT_FIRST_PASS_BUDGET " SBRT_STRINGIFY(32) "\n";
static_assert(sbrt::FIRST_PASS_TILE == 8 && sbrt::FIRST_PASS_BUDGET == 32,
              "FIRST_PASS_DEFINES follow cpu_tracing.hpp");

/// Whether the rays meet nothing translucent: a ray's outputs are then its
/// first hit's alone, whatever it crossed before.
bool every_stratum_opaque(const sbrt::Tracer &tracer)
{
    const std::vector<double> &extinction = tracer.scene().translucency.extinction;
    return std::all_of(extinction.begin(), extinction.end(),
                       [](double e) { return e == std::numeric_limits<double>::infinity(); });
}

/// The entry file of `pass`'s program (its main()).
const char *entry_source(Pass pass)
{
    switch (pass) {
    case Pass::records: return SHADER_RECORDS;
    case Pass::kernel_depth: return SHADER_KERNEL_DEPTH;
    case Pass::kernel_normals: return SHADER_KERNEL_NORMALS;
    case Pass::kernel_across: return SHADER_KERNEL_ACROSS;
    case Pass::kernel_shade: return SHADER_KERNEL_SHADE;
    case Pass::first_pass: return SHADER_FIRST_PASS;
    default: return SHADER_SHADE; // shade, shade_boreholes
    }
}

} // namespace

/// The sources of `pass` for the model held in `form`;
/// with `drape`, a drape's colours among the outputs (SBRT_DRAPE); with
/// `paint`, the shading pass's colours by voxel (SBRT_PAINT).
std::vector<const char *> pass_sources(Pass pass, const ModelForm &form,
                                       const sbrt::Tracer &tracer, bool drape, bool paint)
{
    const sbrt::Model &model = tracer.model();
    // a paged model's blocks are found through the page table (SBRT_PAGED)
    const unsigned count_bytes = form.paged ? 4 : model.index().count_bytes();
    // the normals pass reads a face's normal as shading does
    const bool shade = pass == Pass::shade || pass == Pass::shade_boreholes ||
                       pass == Pass::kernel_shade || pass == Pass::kernel_normals;
    // overlays are shaded where they are met (a hit record lacks their
    // surfaces' normals); boreholes with the model in a pass of their own
    // over the tiles they may cover: every other ray walks the model alone
    sbrt::GpuOverlayMode overlays =
        pass == Pass::shade ? sbrt::gpu_overlay_mode(tracer) : sbrt::GpuOverlayMode::none;
    // ...where it keeps each pixel's t of its hit for the boreholes' pass
    const bool hit_t = overlays == sbrt::GpuOverlayMode::with_model;
    if (overlays == sbrt::GpuOverlayMode::with_model)
        overlays = sbrt::GpuOverlayMode::none;
    if (pass == Pass::shade_boreholes)
        overlays = sbrt::GpuOverlayMode::with_model;
    const bool kernel = pass == Pass::kernel_depth || pass == Pass::kernel_normals ||
                        pass == Pass::kernel_across || pass == Pass::kernel_shade;
    return {"#version 450\n",
            form.layout == sbrt::GpuLayout::textures ? "#define SBRT_TEXTURES 1\n" : "",
            form.paged ? "#define SBRT_PAGED 1\n" : "",
            form.column_tops ? "#define SBRT_COLUMN_TOPS 1\n" : "",
            form.column_pages ? "#define SBRT_COLUMN_PAGES 1\n" : "",
            form.column_ranges ? "#define SBRT_COLUMN_RANGES 1\n" : "",
            compact_on_gpu(model) ? "#define SBRT_COMPACT_INTERVALS 1\n" : "",
            count_bytes == 1   ? "#define SBRT_COUNT_BYTES 1\n"
            : count_bytes == 2 ? "#define SBRT_COUNT_BYTES 2\n"
                               : "#define SBRT_COUNT_BYTES 4\n",
            shade ? "#define SBRT_SHADE 1\n" : "",
            drape && shade ? "#define SBRT_DRAPE 1\n" : "",
            paint && pass == Pass::shade ? "#define SBRT_PAINT 1\n" : "",
            kernel ? "#define SBRT_KERNEL 1\n" : "",
            pass == Pass::shade_boreholes ? "#define SBRT_TILE_LIST 1\n" : "",
            // the boreholes' pass traces again only where the ray is in
            // their boxes (or the model pass's hit may be drilled away)
            pass == Pass::shade_boreholes && every_stratum_opaque(tracer)
                ? "#define SBRT_BOX_SPANS 1\n"
                : "",
            hit_t ? "#define SBRT_HIT_T 1\n" : "",
            overlays == sbrt::GpuOverlayMode::alone        ? "#define SBRT_OVERLAYS 1\n"
            : overlays == sbrt::GpuOverlayMode::with_model ? "#define SBRT_BOREHOLES 1\n"
                                                           : "",
            FIRST_PASS_DEFINES,
            SHADER_COMMON_LAYOUT,
            shade ? SHADER_COMMON_SHADE : "",
            kernel || pass == Pass::first_pass ? "" : SHADER_COMMON_RAY,
            sbrt::shaded_on_gpu(overlays) ? SHADER_COMMON_OVERLAYS : "",
            kernel || pass == Pass::first_pass ? "" : SHADER_COMMON_CLIP,
            kernel || pass == Pass::first_pass ? "" : SHADER_COMMON_WALK,
            kernel || pass == Pass::first_pass ? "" : SHADER_COMMON_TRACE_PIXEL,
            kernel ? SHADER_COMMON_KERNEL : "",
            // a hit's kernel normal: the normals and the kernel's shading
            kernel && shade ? SHADER_COMMON_KERNEL_NORMAL : "",
            entry_source(pass)};
}


} // namespace sbrt_gl
