/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   OSMesa context (Mesa before 25.1), built only where
 *            <GL/osmesa.h> exists (SBRT_HAVE_OSMESA); rendering goes to
 *            buffers, the 1x1 colour buffer only satisfies MakeCurrent
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "util/error.hpp"
#include "gl_context.hpp"

#ifdef SBRT_HAVE_OSMESA
// osmesa.h includes GL/gl.h: kept out of every file that includes
// glcorearb.h (their prototypes clash)
#include <GL/osmesa.h>
#include <dlfcn.h>
#endif

namespace sbrt_gl {

#ifdef SBRT_HAVE_OSMESA

namespace {

/// \brief libOSMesa loaded at run time: only a render that asks for
/// OSMesa (or falls back to it) pays for it and for the libLLVM it links;
/// every other run starts without either.
class OsmesaLibrary {
public:
    OsmesaLibrary()
    {
        // RTLD_NODELETE: Mesa keeps global state (its LLVM, per-context
        // allocations) past OSMesaDestroyContext; unmapping the library
        // under it is unsafe, and leak reports then name no module
        for (const char *name : {"libOSMesa.so.8", "libOSMesa.so"})
            if ((handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)))
                break;
        if (!handle_)
            sbrt::fail("osmesa: cannot load libOSMesa.so.8 (", dlerror(),
                       "); install libosmesa6 or use backend=egl");
        load(create_context_attribs, "OSMesaCreateContextAttribs");
        load(make_current, "OSMesaMakeCurrent");
        load(destroy_context, "OSMesaDestroyContext");
        load(get_proc_address, "OSMesaGetProcAddress");
    }
    ~OsmesaLibrary() { dlclose(handle_); }
    OsmesaLibrary(const OsmesaLibrary &) = delete;
    OsmesaLibrary &operator=(const OsmesaLibrary &) = delete;

    decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaDestroyContext) destroy_context = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;

private:
    template <typename Function>
    void load(Function &function, const char *name)
    {
        function = reinterpret_cast<Function>(dlsym(handle_, name));
        if (!function) {
            dlclose(handle_);
            sbrt::fail("osmesa: libOSMesa has no ", name);
        }
    }

    void *handle_ = nullptr;
};

class OsmesaContext : public GlContext {
public:
    OsmesaContext()
    {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                  OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        context_ = osmesa_.create_context_attribs(attributes, nullptr);
        if (!context_)
            sbrt::fail("osmesa: OSMesaCreateContextAttribs (OpenGL 4.5 core) failed");
        if (!osmesa_.make_current(context_, pixel_, GL_UNSIGNED_BYTE, 1, 1)) {
            osmesa_.destroy_context(context_);
            sbrt::fail("osmesa: OSMesaMakeCurrent failed");
        }
    }
    ~OsmesaContext() override { osmesa_.destroy_context(context_); }
    OsmesaContext(const OsmesaContext &) = delete;
    OsmesaContext &operator=(const OsmesaContext &) = delete;

    std::string name() const override { return "osmesa"; }
    GlProc proc_address(const char *function) const override
    {
        return reinterpret_cast<GlProc>(osmesa_.get_proc_address(function));
    }

private:
    OsmesaLibrary osmesa_; ///< before the context: unloaded after it
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
