/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   The OpenGL 4.4+ core entry points the renderer uses, loaded
 *            through the context's getProcAddress (EGL or OSMesa): no
 *            link-time GL library, no global function pointers
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#ifndef SBRT_GL_API_HPP
#define SBRT_GL_API_HPP

#include <GL/glcorearb.h>

#include "gl_context.hpp"

namespace sbrt_gl {

// X(type, name): one line per entry point.
#define SBRT_GL_FUNCTIONS(X)                                                  \
    X(PFNGLGETSTRINGPROC, GetString)                                          \
    X(PFNGLGETERRORPROC, GetError)                                            \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                      \
    X(PFNGLGETINTEGER64VPROC, GetInteger64v)                                  \
    X(PFNGLCREATESHADERPROC, CreateShader)                                    \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                    \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                  \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                      \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                            \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                    \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                  \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                    \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                      \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                    \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                          \
    X(PFNGLPROGRAMPARAMETERIPROC, ProgramParameteri)                          \
    X(PFNGLGETPROGRAMBINARYPROC, GetProgramBinary)                            \
    X(PFNGLPROGRAMBINARYPROC, ProgramBinary)                                  \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                  \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                        \
    X(PFNGLGETPROGRAMRESOURCEINDEXPROC, GetProgramResourceIndex)              \
    X(PFNGLGETPROGRAMRESOURCEIVPROC, GetProgramResourceiv)                    \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                        \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                  \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                        \
    X(PFNGLBUFFERDATAPROC, BufferData)                                        \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                \
    X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                            \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                                  \
    X(PFNGLCOPYBUFFERSUBDATAPROC, CopyBufferSubData)                          \
    X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                              \
    X(PFNGLDISPATCHCOMPUTEINDIRECTPROC, DispatchComputeIndirect)              \
    X(PFNGLCLEARBUFFERSUBDATAPROC, ClearBufferSubData)                        \
    X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                                  \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                      \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                  \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                      \
    X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                                    \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                                  \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                  \
    X(PFNGLFINISHPROC, Finish)                                                \
    X(PFNGLFLUSHPROC, Flush)                                                  \
    X(PFNGLBUFFERSTORAGEPROC, BufferStorage)                                  \
    X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange)                                \
    X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                                      \
    X(PFNGLFENCESYNCPROC, FenceSync)                                          \
    X(PFNGLCLIENTWAITSYNCPROC, ClientWaitSync)                                \
    X(PFNGLDELETESYNCPROC, DeleteSync)                                        \
    X(PFNGLGENQUERIESPROC, GenQueries)                                        \
    X(PFNGLDELETEQUERIESPROC, DeleteQueries)                                  \
    X(PFNGLBEGINQUERYPROC, BeginQuery)                                        \
    X(PFNGLENDQUERYPROC, EndQuery)                                            \
    X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)

/// \brief Entry points of one context; call as gl.GetString(...).
struct GlApi {
#define SBRT_GL_MEMBER(type, name) type name = nullptr;
    SBRT_GL_FUNCTIONS(SBRT_GL_MEMBER)
#undef SBRT_GL_MEMBER

    /// Loads every entry point from the current context; throws
    /// sbrt::Error naming the first one missing.
    explicit GlApi(const GlContext &context);
};

/// Throws sbrt::Error with `what` and the GL error code if one is pending.
void check_gl(const GlApi &gl, const char *what);

} // namespace sbrt_gl

#endif
