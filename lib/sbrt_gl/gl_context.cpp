/****************************************************************************
 * MODULE:    lib/sbrt_gl (r3.sbrt addon)
 * PURPOSE:   Choice of the GL backend
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "gl_context.hpp"

#include <filesystem>
#include <system_error>

#include "util/error.hpp"

namespace sbrt_gl {

std::unique_ptr<GlContext> create_gl_context(const std::string &backend)
{
    if (backend == "egl")
        return create_egl_context();
    if (backend == "osmesa")
        return create_osmesa_context();
    if (backend != "auto")
        sbrt::fail("unknown GL backend <", backend, ">");
    std::string reasons;
    for (auto create : {create_egl_context, create_osmesa_context}) {
        try {
            return create();
        }
        catch (const sbrt::Error &e) {
            reasons += (reasons.empty() ? "" : "; ") + std::string(e.what());
        }
    }
    sbrt::fail("no OpenGL backend works: ", reasons);
}

std::string gpu_device_node()
{
    namespace fs = std::filesystem;
    std::error_code error; // a directory that cannot be read holds none
    for (const fs::directory_entry &entry : fs::directory_iterator("/dev/dri", error))
        if (entry.path().filename().string().rfind("renderD", 0) == 0)
            return entry.path().string();
    for (const char *node : {"/dev/nvidiactl", "/dev/dxg"})
        if (fs::exists(node, error))
            return node;
    return "";
}

bool is_software_renderer(const std::string &renderer)
{
    for (const char *name : {"llvmpipe", "softpipe", "swrast", "Software"})
        if (renderer.find(name) != std::string::npos)
            return true;
    return false;
}

} // namespace sbrt_gl
