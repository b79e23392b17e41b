/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   A headless OpenGL 4.5 core context, current on the calling
 *            thread while the object lives: EGL (device platform, then
 *            surfaceless) or OSMesa, one backend per file
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_CONTEXT_HPP
#define SBRT_GL_CONTEXT_HPP

#include <memory>
#include <string>

namespace sbrt_gl {

using GlProc = void (*)();

class GlContext {
public:
    virtual ~GlContext() = default;
    /// "egl (device)", "egl (surfaceless)" or "osmesa".
    virtual std::string name() const = 0;
    virtual GlProc proc_address(const char *function) const = 0;
};

/// EGL: the first device that makes a context (hardware before Mesa's
/// software device), then the surfaceless platform. Throws sbrt::Error
/// saying what failed.
std::unique_ptr<GlContext> create_egl_context();

/// OSMesa (Mesa before 25.1). Throws sbrt::Error saying what failed, also
/// when the addon was built without OSMesa.
std::unique_ptr<GlContext> create_osmesa_context();

/// backend "egl", "osmesa" or "auto" (EGL, then OSMesa). Throws
/// sbrt::Error listing each backend tried and why it failed.
std::unique_ptr<GlContext> create_gl_context(const std::string &backend);

/// The first device node a hardware OpenGL would go through (a DRM render
/// node, NVIDIA's control device, WSL's /dev/dxg), or "" where there is
/// none: then only a software rasteriser can make a context, and looking
/// for one (loading Mesa and LLVM) can be skipped.
std::string gpu_device_node();

/// Whether a GL_RENDERER string names a software rasteriser (Mesa's
/// llvmpipe, softpipe, swrast, or a driver that says "Software").
bool is_software_renderer(const std::string &renderer);

} // namespace sbrt_gl

#endif
