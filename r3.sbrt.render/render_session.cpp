/****************************************************************************
 * MODULE:    r3.sbrt.render
 * PURPOSE:   One render session shared by the command line, its animation
 *            loop and the view server
 * COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
 ****************************************************************************/
#include "render_session.hpp"

#include <sstream>

#include "frame_cameras.hpp"
#include "material_colors.hpp"
#include "model_reading.hpp"
#include "prepared_scene.hpp"
#include "property_colors.hpp"
#include "sbrt_store.hpp"
#include "request_error.hpp"
#include "scene/camera_path.hpp"
#include "scene_setup.hpp"
#include "skipping_report.hpp"
#include "texture_input.hpp"
#include "builders/voxel_selection.hpp"
#include "frame/fitting_exaggeration.hpp"
#include "tracing/scene_pruning.hpp"

namespace {

/// The key of each stage: the keys of the request's parts it consumes
/// (each part keys itself beside its options, *_part.cpp).

/// The model as read: its input and colours, and where only the blocks
/// under the region are read, the region.
std::string model_key(const RenderRequest &request, const struct Cell_head &region)
{
    std::ostringstream key;
    key << std::hexfloat << key_of<InputPart, ColorsPart>(request);
    if (sees_only_the_region(request))
        key << region.north << ' ' << region.south << ' ' << region.east << ' '
            << region.west;
    return key.str();
}

/// The prepared scene, the camera's share included (the planes of
/// section= and the split direction of -m face it). Camera, light and
/// outputs are not in it: the shading is set for every frame.
std::string scene_key(const RenderRequest &r, const sbrt::Camera &camera)
{
    return key_of<ExaggerationPart, BackendPart, StrataPart, SelectionPart>(r) +
           r.SectionsPart::key(camera) + '\n' + r.BoreholesPart::key(camera);
}

} // namespace

void RenderSession::load(RenderRequest &request, const struct Cell_head &region)
{
    const std::string key = model_key(request, region);
    if (!model_ || key != model_key_) {
        drop_scene();
        drape_.reset();
        property_.reset();
        fade_.reset();
        selected_.reset();
        selection_key_.clear();
        channels_.reset();
        frame_.reset();
        drape_key_.clear();
        property_key_.clear();
        model_key_.clear();
        model_ = std::make_unique<sbrt::Model>(read_model(request, region));
        apply_color_option(request, *model_);
        fitted_zexag_ = sbrt::fitting_exaggeration(*model_); // once a model
        model_key_ = key;
    }
    if (request.zexag_fitted)
        request.zexag = fitted_zexag_;
    if (!frame_ || frame_->zexag() != request.zexag)
        frame_ = sbrt::CoordinateFrame::of(*model_, request.zexag);
}

std::vector<sbrt::Camera> RenderSession::cameras(const RenderRequest &request,
                                                 const struct Cell_head &region) const
{
    std::vector<sbrt::Camera> cameras = frame_cameras(request, *model_, *frame_, region);
    if (request.tile)
        for (sbrt::Camera &camera : cameras)
            camera = camera.window((*request.tile)[0], (*request.tile)[2],
                                   (*request.tile)[1], (*request.tile)[3]);
    return cameras;
}

void RenderSession::prepare(const RenderRequest &request, const sbrt::Camera &camera,
                            bool one_view)
{
    prepare_drape(request);
    prepare_property(request);
    prepare_selection(request);
    prepare_scene_for(request, camera, one_view);
    if (renderer_)
        renderer_->set_shading(
            make_shading(request, drape_.get(), property_.get(), fade_.get()));
}

void RenderSession::prepare_drape(const RenderRequest &request)
{
    // the drape of texture=
    const std::string drape = key_of<DrapePart>(request);
    if (drape != drape_key_) {
        drop_scene();
        drape_.reset();
        drape_key_.clear();
        if (!request.texture.empty())
            drape_ = std::make_unique<sbrt::Drape>(*model_, read_texture(request.texture),
                                                   request.texture_blend);
        drape_key_ = drape;
    }
}

void RenderSession::prepare_property(const RenderRequest &request)
{
    // the property of property=, over the model as read
    const std::string property = key_of<PropertyPart>(request);
    if (property != property_key_) {
        property_.reset();
        fade_.reset();
        property_key_.clear();
        if (!request.fade.empty()) {
            const sbrt::PropertyChannels &all = *channels(request);
            RenderRequest asked = request;
            asked.property = {request.fade};
            const std::vector<size_t> channel = property_channels(asked, &all);
            const sbrt::ChannelInfo &info = all.info(channel[0]);
            // a channel in % (its unit or its kind) fades over 0-100
            const sbrt::ChannelKind kind = info.known_kind();
            const bool in_percent = info.unit == "%" || kind == sbrt::ChannelKind::probability ||
                                    kind == sbrt::ChannelKind::percentage;
            double low = 0, high = in_percent ? 100 : info.physical(float(info.max));
            if (request.fade_range) {
                low = (*request.fade_range)[0];
                high = (*request.fade_range)[1];
            }
            if (!(high > low))
                bad_request(_("fade=%s: its values go up to %g only; give fade_range=low,high"),
                            request.fade.c_str(), high);
            fade_ = std::make_unique<sbrt::UncertaintyFade>(*model_, channels_, channel[0],
                                                            low, high);
        }
        if (!request.property.empty()) {
            const std::vector<size_t> summed = property_channels(request, channels(request));
            const auto [low, high] = property_range(*channels_, summed);
            property_ = std::make_unique<sbrt::PropertyPaint>(
                *model_, channels_, summed,
                property_ramp(request.property_color, low, high));
            property_frames_ = 0;
        }
        property_key_ = property;
    }
}

void RenderSession::prepare_selection(const RenderRequest &request)
{
    // select=: only the voxels meeting the condition are solid
    const std::string selection = key_of<SelectionPart>(request);
    if (selection != selection_key_) {
        drop_scene();
        selected_.reset();
        selection_key_.clear();
        if (!request.select.empty()) {
            const sbrt::PropertyChannels &all = *channels(request);
            sbrt::Selection selection;
            try {
                selection = sbrt::parse_selection(request.select, all);
            }
            catch (const sbrt::Error &e) {
                bad_request(_("select=%s: %s"), request.select.c_str(), e.what());
            }
            selected_ = std::make_unique<sbrt::Model>(
                sbrt::select_voxels(*model_, all, selection, unsigned(request.threads)));
            const sbrt::Stats s = selected_->stats();
            G_verbose_message(_("select=%s: %llu solid intervals of %llu"),
                              request.select.c_str(), (unsigned long long)s.solid_intervals,
                              (unsigned long long)model_->stats().solid_intervals);
        }
        selection_key_ = selection;
    }
}

void RenderSession::prepare_scene_for(const RenderRequest &request, const sbrt::Camera &camera,
                                      bool one_view)
{
    const std::string key = scene_key(request, camera);
    if (!renderer_ || key != scene_key_) {
        drop_scene();
        // hidden strata, planes, boreholes, fence, translucency
        PreparedScene prepared =
            prepare_scene(request, selected_ ? *selected_ : *model_, camera);
        const std::string context = key_of<BackendPart>(request);
        if (context != context_key_) {
            context_.reset(); // before another on the same display
            context_key_.clear();
            context_ = choose_gl_context(request);
            context_key_ = context;
        }
        // on a GPU what no ray of a single view reaches is not uploaded
        // (the CPU never reads it anyway)
        const sbrt::Scene &scene = prepared.scene;
        if (one_view && context_ && scene.skip_empty_space && scene.draw_model) {
            sbrt::Pruning pruning =
                sbrt::prune_for_view(prepared.model, request.zexag, scene, camera);
            report_pruning(pruning, scene.planes.size());
            prepared.model = std::move(pruning.model);
        }
        request_ = std::make_unique<RenderRequest>(request);
        const bool sweep = request.frames > 1 && request.path == sbrt::PathKind::sweep;
        if (sweep) { // each frame's renderer moves the plane (sweep_to)
            prepared_model_ = std::make_unique<sbrt::Model>(std::move(prepared.model));
            prepared_scene_ = std::move(prepared.scene);
        }
        else {
            build_renderer(std::move(prepared.model), std::move(prepared.scene));
            report_pyramid(renderer_->tracer().pyramid(), renderer_->model());
        }
        scene_key_ = key;
    }
}

const sbrt::PropertyChannels *RenderSession::stored_channels(const RenderRequest &request)
{
    if (!channels_)
        channels_ = sbrt_grass::read_channels_map(request.input.c_str(), *model_);
    return channels_.get();
}

const sbrt::PropertyChannels *RenderSession::channels(const RenderRequest &request)
{
    if (!stored_channels(request))
        bad_request(_("SBRT <%s> has no property channels: property= and select= need an "
                      "SBRT imported with properties= (r3.sbrt.convert file=... "
                      "properties=...)"),
                    request.input.c_str());
    return channels_.get();
}

void RenderSession::sweep_to(int k)
{
    if (!prepared_model_)
        bad_request(_("Internal error: a sweep's frame without a sweep"));
    sbrt::Scene swept = prepared_scene_;
    // the sweep moves the first plane= (else section=) across the box of
    // the model as prepared
    const sbrt::CoordinateFrame box =
        sbrt::CoordinateFrame::of(*prepared_model_, request_->zexag);
    swept.planes.front() =
        sbrt::swept_plane(prepared_scene_.planes.front(), box, k, request_->frames);
    backend_.reset(); // it refers to the previous frame's renderer
    renderer_.reset();
    build_renderer(*prepared_model_, std::move(swept));
}

void RenderSession::drop_scene()
{
    backend_.reset(); // it refers to the renderer
    renderer_.reset();
    prepared_model_.reset();
    scene_key_.clear();
}

void RenderSession::build_renderer(sbrt::Model model, sbrt::Scene scene)
{
    renderer_ = std::make_unique<sbrt::Renderer>(
        std::move(model), request_->zexag, std::move(scene),
        make_shading(*request_, drape_.get(), property_.get(), fade_.get()),
        sbrt::RenderSettings{unsigned(request_->threads), true, 0});
    backend_ = std::make_unique<Backend>(*request_, *renderer_, context_.get());
}

void RenderSession::render(const sbrt::Camera &camera, const sbrt::Outputs &outputs,
                           const sbrt::BandSink &sink)
{
    // a property's sums are kept per block once a second frame shows it
    if (property_ && property_frames_++ > 0)
        property_->keep_block_sums();
    backend_->render(camera, outputs, sink);
}
