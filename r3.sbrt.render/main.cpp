/****************************************************************************
 * MODULE:    r3.sbrt.render
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Renders an SBRT with an exact ray caster and writes the image
 *            (and material, elevation, depth of the first hit) as rasters
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <cstdlib>

#include "backend.hpp"
#include "error.hpp"
#include "grass.hpp"
#include "hidden_materials.hpp"
#include "material_colors.hpp"
#include "raster_output.hpp"
#include "render_options.hpp"
#include "sbrt_store.hpp"
#include "scene_camera.hpp"
#include "scene_setup.hpp"
#include "shading.hpp"

namespace {

void run(const RenderRequest &request)
{
    sbrt::Model model = sbrt_grass::read_sbrt_map(request.input.c_str());
    apply_color_option(request, model);
    if (!request.hide.empty())
        model = sbrt::hide_materials(model, hidden_materials(request, model));
    struct Cell_head region;
    G_get_window(&region);
    // the camera frames the whole model's box, whatever is hidden or cut
    const sbrt::Camera camera =
        make_camera(request, sbrt::Tracer(model, request.zexag), region);
    const sbrt::Tracer tracer(model, request.zexag, clip_planes(request, camera));

    sbrt::Shading shading;
    shading.light = sbrt::Shading::light_from(request.light_azimuth,
                                              request.light_elevation);
    shading.ambient = request.ambient;
    shading.background = request.background;
    shading.normals = request.normals == "kernel" ? sbrt::Normals::kernel
                                                  : sbrt::Normals::face;
    shading.kernel = request.kernel;
    shading.smooth = request.smooth;

    std::vector<sbrt::Hit> hits = trace_hits(request, tracer, camera);
    const sbrt::Image image = sbrt::shade(tracer, camera, std::move(hits), shading,
                                          unsigned(request.threads));
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
