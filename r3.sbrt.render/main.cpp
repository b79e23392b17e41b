/****************************************************************************
 * MODULE:    r3.sbrt.render
 * AUTHOR(S): r3.sbrt authors
 * PURPOSE:   Renders an SBRT with an exact ray caster and writes the image
 *            (and material, elevation, depth of the first hit) as rasters
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <optional>
#include <vector>

#include "annotation_setup.hpp"
#include "backend.hpp"
#include "scene/camera_path.hpp"
#include "frame_cameras.hpp"
#include "frames.hpp"
#include "shading/drape.hpp"
#include "util/error.hpp"
#include "grass.hpp"
#include "material_colors.hpp"
#include "model_reading.hpp"
#include "prepared_scene.hpp"
#include "raster_output.hpp"
#include "scene/scene_pruning.hpp"
#include "render_options.hpp"
#include "sbrt_choices.hpp"
#include "sbrt_store.hpp"
#include "scene_camera.hpp"
#include "skipping_report.hpp"
#include "texture_input.hpp"
#include "view_server.hpp"

namespace {

/// Traces, shades and writes one image of `renderer` seen by `camera`, on
/// `backend` (the renderer's).
void render_frame(const RenderRequest &request, const sbrt::Renderer &renderer,
                  Backend &backend, const sbrt::Camera &camera,
                  const struct Cell_head &region)
{
    struct Cell_head window =
        request.view.kind == sbrt::ViewKind::top
            ? region
            : image_window(region, request.height, request.width);
    if (request.tile)
        window = tile_window(window, *request.tile);
    ImageMaps maps(request, window,
                   make_annotations(request, renderer.tracer(), camera, region));
    backend.render(camera, maps.outputs(),
                   [&](const sbrt::Band &band) { maps.write(band); });
    maps.close(renderer.model());
}

void run(const RenderRequest &request)
{
    check_png_pattern(request.png);
    check_video(request);
    // 1. the model, its colours, the drape, the cameras
    struct Cell_head region;
    G_get_window(&region);
    sbrt::Model model = read_model(request, region);
    apply_color_option(request, model);
    std::optional<sbrt::Drape> drape;
    if (!request.texture.empty())
        drape.emplace(model, read_texture(request.texture), request.texture_blend);
    // the camera frames the model as read, whatever is hidden or cut: the
    // view stays put while strata are switched off (its box only: no
    // pyramid for this tracer)
    sbrt::Scene framing;
    framing.skip_empty_space = false;
    std::vector<sbrt::Camera> cameras =
        frame_cameras(request, sbrt::Tracer(model, request.zexag, framing), region);
    if (request.tile)
        for (sbrt::Camera &camera : cameras)
            camera = camera.window((*request.tile)[0], (*request.tile)[2],
                                   (*request.tile)[1], (*request.tile)[3]);

    // 2. the scene: hidden strata, planes, boreholes, fence, translucency
    // (sections and split logs face the first frame's camera)
    PreparedScene prepared = prepare_scene(request, std::move(model), cameras.front());
    model = std::move(prepared.model);
    const sbrt::Scene &scene = prepared.scene;

    // 3. the backend; on a GPU what no ray of a single view reaches is not
    // uploaded (the CPU never reads it anyway)
    const std::unique_ptr<sbrt_gl::GlContext> context = choose_gl_context(request);
    if (context && scene.skip_empty_space && scene.draw_model && request.frames == 1) {
        sbrt::Pruning pruning = sbrt::prune_for_view(
            sbrt::Tracer(model, request.zexag, scene), cameras.front());
        report_pruning(pruning, scene.planes.size());
        model = std::move(pruning.model);
    }

    // 4. prepare once (a sweep: once a frame, its plane moved), then
    // trace, shade and write band by band, frame by frame
    const sbrt::Shading shading = make_shading(request, drape ? &*drape : nullptr);
    const sbrt::RenderSettings settings{unsigned(request.threads), true, 0};
    const bool sweep = request.frames > 1 && request.path == sbrt::PathKind::sweep;
    // a sweep's plane moves across the box of the model as prepared (its
    // box only: no pyramid for this tracer)
    sbrt::Scene box_only;
    box_only.skip_empty_space = false;
    std::optional<sbrt::Tracer> box;
    if (sweep)
        box.emplace(model, request.zexag, box_only);
    std::optional<sbrt::Renderer> renderer;
    std::optional<Backend> backend; // a GPU keeps the renderer's model
    if (!sweep) {
        renderer.emplace(std::move(model), request.zexag, scene, shading, settings);
        report_pyramid(renderer->tracer());
        backend.emplace(request, *renderer, context.get());
    }
    int skipped = 0;
    for (int k = request.first_frame; k <= request.last_frame; ++k) {
        if (request.frames > 1)
            G_percent(k - request.first_frame, request.last_frame - request.first_frame + 1,
                      1);
        const RenderRequest frame = frame_request(request, k);
        if (request.frames > 1 && !request.overwrite && frame_finished(frame)) {
            ++skipped; // a rerun: finished frames stay as they are
            continue;
        }
        if (sweep) {
            sbrt::Scene swept = scene;
            // the sweep moves the first plane= (else section=)
            swept.planes.front() =
                sbrt::swept_plane(scene.planes.front(), *box, k, request.frames);
            backend.reset(); // it refers to the previous frame's renderer
            renderer.emplace(model, request.zexag, std::move(swept), shading, settings);
            backend.emplace(request, *renderer, context.get());
        }
        render_frame(frame, *renderer, *backend, cameras[size_t(k - 1)], region);
    }
    if (request.frames > 1) {
        G_percent(1, 1, 1);
        if (skipped)
            G_message(_("%d frames were there already and were kept (--overwrite "
                        "renders them again)"),
                      skipped);
    }
    register_frames(request);
    assemble_video(request);
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
    if (argc == 2 && std::strcmp(argv[1], "--serve") == 0) {
        // g.gui.sbrt's view server: requests on stdin, frames on stdout
        try {
            serve_views(options, stdin, stdout);
        }
        catch (const std::exception &e) {
            G_fatal_error(_("The view server failed: %s"), e.what());
        }
        exit(EXIT_SUCCESS);
    }
    sbrt_grass::offer_sbrts_in_dialog(options.input, argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const RenderRequest request = read_render_options(options);
    try {
        run(request);
    }
    catch (const sbrt::Error &e) {
        G_fatal_error("%s", e.what());
    }
    catch (const std::bad_alloc &) {
        G_fatal_error(_("Out of memory while rendering <%s>: render a smaller image "
                        "(size=; view=top: g.region rows= cols=) or fewer outputs"),
                      request.input.c_str());
    }
    catch (const std::exception &e) {
        // thrown on a worker thread and carried here (sbrt::for_each_row)
        G_fatal_error(_("Rendering <%s> failed: %s"), request.input.c_str(), e.what());
    }
    exit(EXIT_SUCCESS);
}
