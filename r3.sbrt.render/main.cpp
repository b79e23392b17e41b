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
#include <optional>
#include <vector>

#include "annotation_setup.hpp"
#include "frame_claim.hpp"
#include "frames.hpp"
#include "grass.hpp"
#include "raster_output.hpp"
#include "render_options.hpp"
#include "render_session.hpp"
#include "sbrt_choices.hpp"
#include "util/error.hpp"
#include "view_server.hpp"
#include "module_errors.hpp"

namespace {

/// Traces, shades and writes one image of `session` seen by `camera`.
void render_frame(const RenderRequest &request, RenderSession &session,
                  const sbrt::Camera &camera, const struct Cell_head &region)
{
    struct Cell_head window =
        request.view.kind == sbrt::ViewKind::top
            ? region
            : image_window(region, request.height, request.width);
    if (request.tile)
        window = tile_window(window, *request.tile);
    ImageMaps maps(request, window,
                   make_annotations(request, session.renderer().model(), session.frame(),
                                    camera, region, session.property(), session.fade()));
    session.render(camera, maps.outputs(), [&](const sbrt::Band &band) { maps.write(band); });
    maps.close(session.renderer().model(), session.property());
}

/// Says which exaggeration a render without zexag= got (the frame's), and
/// from what: the frame's extent, and its box's height from the bottom to
/// the highest top.
void report_fitted_exaggeration(const sbrt::CoordinateFrame &frame)
{
    const sbrt::Frame &f = frame.grid();
    const char *units = G_database_unit_name(TRUE);
    G_message(_("Vertical exaggeration %g, fitted to the model's extent (%g x %g %s) "
                "and thickness (%g %s); zexag= sets another"),
              frame.zexag(), f.east - f.west, f.north - f.south, units,
              frame.top_elevation() - f.bottom, units);
}

void run(const RenderRequest &asked)
{
    // video= alone: its frames in a temporary folder, removed after
    RenderRequest request = asked;
    std::optional<TemporaryFrames> video_frames;
    if (!request.video.empty() && request.png.empty() && request.frames > 1) {
        video_frames.emplace(request);
        request.png = video_frames->png();
    }
    check_png_pattern(request.png);
    check_video(request);
    struct Cell_head region;
    G_get_window(&region);
    // load, frame, prepare once (a sweep: once a frame, its plane moved),
    // then trace, shade and write band by band, frame by frame
    RenderSession session;
    session.load(request, region);
    if (request.zexag_fitted && request.view.kind != sbrt::ViewKind::top)
        report_fitted_exaggeration(session.frame());
    const std::vector<sbrt::Camera> cameras = session.cameras(request, region);
    session.prepare(request, cameras.front(), request.frames == 1);
    const bool sweep = request.frames > 1 && request.path == sbrt::PathKind::sweep;
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
        // jobs sharing their PNG files: no two at one frame (and a frame
        // another job finished meanwhile stays)
        const FrameClaim claim(request.frames > 1 ? frame.png : std::string(), k);
        if (request.frames > 1 && !request.overwrite && frame_finished(frame)) {
            ++skipped;
            continue;
        }
        if (sweep)
            session.sweep_to(k);
        render_frame(frame, session, cameras[size_t(k - 1)], region);
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
    const OptionTable options = define_render_options();
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
    sbrt_grass::offer_sbrts_in_dialog(options.option("input"), argc, argv);
    if (G_parser(argc, argv))
        exit(EXIT_FAILURE);
    const ParsedRequest parsed = parse_render_request(options, options.parsed_words());
    if (!parsed.request)
        G_fatal_error("%s", parsed.error.c_str());
    const RenderRequest &request = *parsed.request;
    // a worker thread's exception is carried here (sbrt::for_each_row)
    sbrt_grass::run_reporting_errors(
        "rendering", request.input,
        _("render a smaller image (size=; view=top: g.region rows= cols=) or fewer outputs"),
        [&] { run(request); });
    exit(EXIT_SUCCESS);
}
