/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GPU path's programs, built when first asked for
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "program_set.hpp"

#include "shader_sources.hpp"

namespace sbrt_gl {

ProgramSet::ProgramSet(const GlApi &gl, const sbrt::Tracer &tracer, const GpuModel &model,
                       ProgramCache cache)
    : gl_(gl), tracer_(tracer), model_(model), cache_(std::move(cache))
{
}

GlComputeProgram &ProgramSet::get(Pass pass, ProgramVariant variant)
{
    std::unique_ptr<GlComputeProgram> &program = programs_[key(pass, variant)];
    if (program)
        return *program;
    const auto start = Clock::now();
    // the culling of the boreholes' tiles reads no model
    program = std::make_unique<GlComputeProgram>(
        gl_,
        pass == Pass::cull_tiles
            ? std::vector<const char *>{"#version 450\n", SHADER_TILE_CULL}
            : pass_sources(pass, model_.form(), tracer_, variant.drape, variant.paint),
        &cache_);
    build_ms_ += ms_since(start);
    return *program;
}

const GlComputeProgram *ProgramSet::built(Pass pass, ProgramVariant variant) const
{
    const auto found = programs_.find(key(pass, variant));
    return found == programs_.end() ? nullptr : found->second.get();
}

} // namespace sbrt_gl
