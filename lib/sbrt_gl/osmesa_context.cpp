/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   OSMesa context (Mesa before 25.1), built only where
 *            <GL/osmesa.h> exists (SBRT_HAVE_OSMESA); rendering goes to
 *            buffers, the 1x1 colour buffer only satisfies MakeCurrent
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "error.hpp"
#include "gl_context.hpp"

#ifdef SBRT_HAVE_OSMESA
// osmesa.h includes GL/gl.h: kept out of every file that includes
// glcorearb.h (their prototypes clash)
#include <GL/osmesa.h>
#endif

namespace sbrt_gl {

#ifdef SBRT_HAVE_OSMESA

namespace {

class OsmesaContext : public GlContext {
public:
    OsmesaContext()
    {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                  OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_)
            sbrt::fail("osmesa: OSMesaCreateContextAttribs (OpenGL 4.5 core) failed");
        if (!OSMesaMakeCurrent(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
            OSMesaDestroyContext(context_);
            sbrt::fail("osmesa: OSMesaMakeCurrent failed");
        }
    }
    ~OsmesaContext() override { OSMesaDestroyContext(context_); }
    OsmesaContext(const OsmesaContext &) = delete;
    OsmesaContext &operator=(const OsmesaContext &) = delete;

    std::string name() const override { return "osmesa"; }
    GlProc proc_address(const char *function) const override
    {
        return reinterpret_cast<GlProc>(OSMesaGetProcAddress(function));
    }

private:
    OSMesaContext context_ = nullptr;
    unsigned char pixel_[4] = {0, 0, 0, 0};
};

} // namespace

std::unique_ptr<GlContext> create_osmesa_context()
{
    return std::make_unique<OsmesaContext>();
}

#else

std::unique_ptr<GlContext> create_osmesa_context()
{
    sbrt::fail("osmesa: not built in (no <GL/osmesa.h> when the addon was "
               "built; OSMesa is gone from Mesa 25.1 on)");
}

#endif

} // namespace sbrt_gl
