/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Headless EGL context: devices first (EGL_EXT_device_base,
 *            hardware before software), then EGL_MESA_platform_surfaceless;
 *            no surface, no X display
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstring>
#include <sstream>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "util/error.hpp"
#include "gl_context.hpp"

namespace sbrt_gl {

namespace {

std::string egl_error_name(EGLint error)
{
    switch (error) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: {
        std::ostringstream out;
        out << "EGL error 0x" << std::hex << error;
        return out.str();
    }
    }
}

bool has_extension(const char *list, const char *name)
{
    if (!list)
        return false;
    const size_t n = std::strlen(name);
    for (const char *p = list; (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

class EglContext : public GlContext {
public:
    /// Takes an initialised display; throws with the reason on failure.
    EglContext(EGLDisplay display, std::string name)
        : display_(display), name_(std::move(name))
    {
        if (!eglBindAPI(EGL_OPENGL_API))
            fail_here("eglBindAPI(EGL_OPENGL_API)");
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                     EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        if (!has_extension(eglQueryString(display_, EGL_EXTENSIONS),
                           "EGL_KHR_surfaceless_context"))
            fail_here("no EGL_KHR_surfaceless_context");
        context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                    attributes);
        if (context_ == EGL_NO_CONTEXT)
            fail_here("eglCreateContext (OpenGL 4.5 core)");
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            fail_here("eglMakeCurrent");
    }
    ~EglContext() override
    {
        if (context_ != EGL_NO_CONTEXT) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE,
                           EGL_NO_CONTEXT);
            eglDestroyContext(display_, context_);
        }
        eglTerminate(display_);
    }
    EglContext(const EglContext &) = delete;
    EglContext &operator=(const EglContext &) = delete;

    std::string name() const override { return name_; }
    GlProc proc_address(const char *function) const override
    {
        return eglGetProcAddress(function);
    }

private:
    [[noreturn]] void fail_here(const char *what)
    {
        const std::string error = egl_error_name(eglGetError());
        if (context_ != EGL_NO_CONTEXT)
            eglDestroyContext(display_, context_);
        eglTerminate(display_);
        sbrt::fail(name_, ": ", what, " failed (", error, ")");
    }

    EGLDisplay display_;
    std::string name_;
    EGLContext context_ = EGL_NO_CONTEXT;
};

/// Initialises `display`; throws with the reason.
void initialise(EGLDisplay display, const std::string &name)
{
    if (display == EGL_NO_DISPLAY)
        sbrt::fail(name, ": no display (", egl_error_name(eglGetError()), ")");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        sbrt::fail(name, ": eglInitialize failed (",
                   egl_error_name(eglGetError()), ")");
}

std::unique_ptr<GlContext> try_devices(std::string &why)
{
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!has_extension(client, "EGL_EXT_device_enumeration") ||
        !has_extension(client, "EGL_EXT_platform_device")) {
        why = "egl (device platform): EGL_EXT_device_enumeration or "
              "EGL_EXT_platform_device missing";
        return nullptr;
    }
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
        eglGetProcAddress("eglQueryDevicesEXT"));
    auto query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLint count = 0;
    if (!query_devices || !query_devices(0, nullptr, &count) || count <= 0) {
        why = "egl (device platform): no EGL device";
        return nullptr;
    }
    std::vector<EGLDeviceEXT> devices(count);
    query_devices(count, devices.data(), &count);
    // hardware devices (a DRM node or CUDA) before Mesa's software device
    std::vector<EGLDeviceEXT> ordered;
    for (int pass = 0; pass < 2; ++pass)
        for (EGLDeviceEXT device : devices) {
            const char *extensions =
                query_device_string ? query_device_string(device, EGL_EXTENSIONS)
                                    : nullptr;
            const bool software =
                has_extension(extensions, "EGL_MESA_device_software");
            if (software == (pass == 1))
                ordered.push_back(device);
        }
    std::string reasons;
    for (size_t i = 0; i < ordered.size(); ++i) {
        const std::string name = "egl (device " + std::to_string(i) + ")";
        try {
            EGLDisplay display =
                eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, ordered[i], nullptr);
            initialise(display, name);
            return std::make_unique<EglContext>(display, name);
        }
        catch (const sbrt::Error &e) {
            reasons += (reasons.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    why = reasons;
    return nullptr;
}

} // namespace

std::unique_ptr<GlContext> create_egl_context()
{
    std::string why_devices;
    if (auto context = try_devices(why_devices))
        return context;
    const std::string name = "egl (surfaceless)";
    try {
        if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS),
                           "EGL_MESA_platform_surfaceless"))
            sbrt::fail(name, ": EGL_MESA_platform_surfaceless missing");
        EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA,
                                                   EGL_DEFAULT_DISPLAY, nullptr);
        initialise(display, name);
        return std::make_unique<EglContext>(display, name);
    }
    catch (const sbrt::Error &e) {
        sbrt::fail(why_devices, "; ", e.what());
    }
}

} // namespace sbrt_gl
