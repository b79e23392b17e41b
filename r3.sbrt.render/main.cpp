/****************************************************************************
 * MODULE:    r3.sbrt.render
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Renders an SBRT with an exact ray caster and writes the image
 *            (and material, elevation, depth of the first hit) as rasters
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <chrono>
#include <cstdlib>

#include "cpu_renderer.hpp"
#include "error.hpp"
#include "grass.hpp"
#include "raster_output.hpp"
#include "render_options.hpp"
#include "sbrt_store.hpp"
#include "scene_camera.hpp"

namespace {

void run(const RenderRequest &request)
{
    const sbrt::Model model = sbrt_grass::read_sbrt_map(request.input.c_str());
    struct Cell_head region;
    G_get_window(&region);
    const sbrt::Tracer tracer(model, request.zexag);
    const sbrt::Camera camera = make_camera(request, tracer, region);

    sbrt::Shading shading;
    shading.light = sbrt::Shading::light_from(request.light_azimuth,
                                              request.light_elevation);
    shading.ambient = request.ambient;
    shading.background = request.background;

    G_verbose_message(_("Backend: cpu (exact double-precision ray caster)"));
    const auto start = std::chrono::steady_clock::now();
    const sbrt::Image image = sbrt::render_cpu(model, camera, request.zexag,
                                               shading, unsigned(request.threads));
    const double ms = std::chrono::duration<double, std::milli>(
                          std::chrono::steady_clock::now() - start)
                          .count();
    G_verbose_message(_("Rendered %d x %d pixels in %.1f ms (%.2f Mrays/s)"),
                      image.cols, image.rows, ms,
                      image.rows * double(image.cols) / ms / 1000);
    write_image_maps(request, model, image);
}

} // namespace

int main(int argc, char *argv[])
{
    G_gisinit(argv[0]);
    GModule *module = G_define_module();
    G_add_keyword(_("raster3d"));
    G_add_keyword(_("visualization"));
    G_add_keyword(_("geology"));
    G_add_keyword(_("ray casting"));
    G_add_keyword(_("SBRT"));
    module->description =
        _("Renders a stack-based terrain model (SBRT) with an exact ray "
          "caster into raster maps.");
    const RenderOptions options = define_render_options();
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const RenderRequest request = read_render_options(options);
    try {
        run(request);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", e.what());
    }
    exit(EXIT_SUCCESS);
}
