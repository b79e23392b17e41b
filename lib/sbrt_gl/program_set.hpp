/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The GPU path's programs, keyed by pass and variant: each built
 *            (compiled, or loaded from the program cache) when first asked
 *            for, and kept for the tracer's life
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_PROGRAM_SET_HPP
#define SBRT_GL_PROGRAM_SET_HPP

#include <map>
#include <memory>

#include "gl_objects.hpp"
#include "gpu_internal.hpp"
#include "gpu_model.hpp"
#include "program_cache.hpp"
#include "tracing/tracer.hpp"

namespace sbrt_gl {

/// What makes a pass's program one of several: a drape's colours among
/// its outputs (SBRT_DRAPE), or colours by voxel (SBRT_PAINT).
struct ProgramVariant {
    bool drape = false;
    bool paint = false;
};

/// \brief The programs of one tracer's passes over its model (the form
/// the GpuModel holds it in, pass_sources). Holds references to all three;
/// the context must be current.
class ProgramSet {
public:
    ProgramSet(const GlApi &gl, const sbrt::Tracer &tracer, const GpuModel &model,
               ProgramCache cache);

    /// The program of `pass` in `variant`, built when first asked for.
    GlComputeProgram &get(Pass pass, ProgramVariant variant = {});
    /// The same where it was built; null else.
    const GlComputeProgram *built(Pass pass, ProgramVariant variant = {}) const;
    /// Milliseconds spent building programs so far.
    double build_ms() const { return build_ms_; }

private:
    static int key(Pass pass, ProgramVariant variant)
    {
        return int(pass) * 4 + (variant.drape ? 1 : 0) + (variant.paint ? 2 : 0);
    }

    const GlApi &gl_;
    const sbrt::Tracer &tracer_;
    const GpuModel &model_;
    ProgramCache cache_;
    std::map<int, std::unique_ptr<GlComputeProgram>> programs_;
    double build_ms_ = 0;
};

} // namespace sbrt_gl

#endif
