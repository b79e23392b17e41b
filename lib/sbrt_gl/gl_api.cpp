/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Loading of the GL entry points
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gl_api.hpp"

#include "util/error.hpp"

namespace sbrt_gl {

GlApi::GlApi(const GlContext &context)
{
#define SBRT_GL_LOAD(type, function)                                          \
    function = reinterpret_cast<type>(context.proc_address("gl" #function));  \
    if (!function)                                                            \
        sbrt::fail(context.name(), ": OpenGL entry point gl" #function        \
                   " is missing");
    SBRT_GL_FUNCTIONS(SBRT_GL_LOAD)
#undef SBRT_GL_LOAD
}

void check_gl(const GlApi &gl, const char *what)
{
    const GLenum error = gl.GetError();
    if (error != GL_NO_ERROR)
        sbrt::fail("OpenGL error 0x", std::hex, error, " in ", what);
}

} // namespace sbrt_gl
